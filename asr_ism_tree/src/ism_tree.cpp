#include "asr_ism_tree/ism_tree.hpp"

#include <algorithm>
#include <sstream>

#include "asr_common/input_error.hpp"
#include "asr_ism/input_limits.hpp"

namespace asr_ism_tree {

using asr_common::InputError;

int IsmTree::height() const {
  return level.empty() ? 0 : *std::max_element(level.begin(), level.end()) + 1;
}

std::size_t IsmTree::leafCount() const {
  std::size_t count = 0;
  for (const auto& ism : isms) {
    for (const auto& member : ism.members) {
      if (!member.isPlaceholder())
        ++count;
    }
  }
  return count;
}

std::size_t IsmTree::relativePoseCount() const {
  std::size_t count = 0;
  for (const auto& ism : isms)
    count += ism.relativePoseCount();
  return count;
}

int IsmTree::indexOf(const std::string& ism_name) const {
  for (std::size_t i = 0; i < isms.size(); ++i) {
    if (isms[i].name == ism_name)
      return static_cast<int>(i);
  }
  return -1;
}

int IsmTree::placeholderMemberInParent(int ism) const {
  const int parent_ism = parent.at(ism);
  if (parent_ism < 0)
    return -1;
  const auto& members = isms.at(parent_ism).members;
  for (std::size_t m = 0; m < members.size(); ++m) {
    if (members[m].child_ism == ism)
      return static_cast<int>(m);
  }
  return -1;
}

void IsmTree::validateExtent(const std::string& what) const {
  const std::string named = what + ", scene '" + scene + "'";
  asr_ism::checkRecognitionParameters(parameters, named);
  double longest = 0.0;
  for (const auto& ism : isms) {
    for (const auto& member : ism.members) {
      for (const auto& relative : member.relative_poses) {
        const double length = relative.reference_in_member.position.norm();
        if (length > asr_ism::kMaxRelationLength) {
          std::ostringstream message;
          message << named << ": ISM '" << ism.name << "' relates " << member.object.toString()
                  << " to its reference over " << length << " m, more than the "
                  << asr_ism::kMaxRelationLength << " m a scene may span";
          throw InputError(message.str());
        }
        longest = std::max(longest, length);
      }
    }
  }
  asr_ism::checkVotingExtent(parameters.bin_size, height(), longest, named);
}

void IsmTree::validate(const std::string& what) const {
  const auto fail = [&](const std::string& problem) {
    throw InputError(what + ", scene '" + scene + "': " + problem);
  };
  if (isms.empty())
    fail("the tree has no ISM");
  if (parent.size() != isms.size() || level.size() != isms.size()) {
    fail("parent and level links do not match the ISMs");
  }
  if (parent[0] != -1 || level[0] != 0)
    fail("the first ISM is not the root");
  for (std::size_t i = 0; i < isms.size(); ++i) {
    if (isms[i].members.empty())
      fail("ISM '" + isms[i].name + "' has no member");
    for (const auto& member : isms[i].members) {
      if (member.relative_poses.empty()) {
        fail("ISM '" + isms[i].name + "' has no relative pose for " + member.object.toString());
      }
      if (!member.isPlaceholder()) {
        if (topology.indexOf(member.object) < 0) {
          fail("ISM '" + isms[i].name + "' names unknown object " + member.object.toString());
        }
        continue;
      }
      const int child = member.child_ism;
      if (child <= 0 || child >= static_cast<int>(isms.size()) ||
          parent[child] != static_cast<int>(i) || level[child] != level[i] + 1) {
        fail("ISM '" + isms[i].name + "' has a broken link to a child ISM");
      }
    }
    if (i > 0 && placeholderMemberInParent(static_cast<int>(i)) < 0) {
      fail("ISM '" + isms[i].name + "' is not referenced by its parent");
    }
  }
  validateExtent(what);
}

}  // namespace asr_ism_tree
