#include "object_subsets.hpp"

#include <algorithm>
#include <cmath>

namespace asr_ism_tree {
namespace {

// Objectives within this of each other are equal (rounding of sums of similarities).
constexpr double kMargin = 1e-9;

bool contains(ObjectSet set, int object) {
  return ((set >> object) & 1U) != 0U;
}

}  // namespace

ObjectSubsetSearch::ObjectSubsetSearch(Bound bound, ObjectSet seen, double best, bool completed)
    : bound_(std::move(bound)), best_(best) {
  report(seen, best, completed);
}

double ObjectSubsetSearch::bar() const {
  return best_ + kMargin;
}

bool ObjectSubsetSearch::covered(ObjectSet subset) const {
  return std::any_of(completed_.begin(), completed_.end(),
                     [&](ObjectSet done) { return (subset & ~done) == 0U; });
}

void ObjectSubsetSearch::pushSubsetsOf(ObjectSet subset) {
  for (int object = 0; object < 64; ++object) {
    if (!contains(subset, object))
      continue;
    const ObjectSet smaller = subset & ~(ObjectSet{1} << object);
    if (queued_.insert(smaller).second) {
      const double bound = bound_(smaller);
      pending_.emplace(std::llround(bound / kMargin), smaller, bound);
    }
  }
}

std::optional<ObjectSet> ObjectSubsetSearch::next() {
  while (!pending_.empty()) {
    const auto [level, subset, bound] = *pending_.begin();
    if (bound <= bar())
      break;  // neither this one nor any after it can beat the best
    pending_.erase(pending_.begin());
    if (!covered(subset))
      return subset;
  }
  pending_.clear();
  return std::nullopt;
}

void ObjectSubsetSearch::report(ObjectSet subset, double best, bool completed) {
  best_ = std::max(best_, best);
  if (completed)
    completed_.push_back(subset);
  else
    pushSubsetsOf(subset);
}

SubsetBound::SubsetBound(const IsmTree& tree, std::vector<double> maximum)
    : tree_(tree), maximum_(std::move(maximum)) {}

double SubsetBound::boundOf(int ism, ObjectSet subset) const {
  double bound = 0.0;
  for (const auto& member : tree_.isms[ism].members) {
    if (member.isPlaceholder())
      bound += boundOf(member.child_ism, subset);
    else
      bound +=
          contains(subset, static_cast<int>(tree_.topology.indexOf(member.object))) ? 1.0 : 0.0;
  }
  return std::min(bound, maximum_[ism]);
}

}  // namespace asr_ism_tree
