#include "asr_ism_tree/tree_generation.hpp"

#include <algorithm>
#include <numeric>

#include "asr_common/input_error.hpp"
#include "asr_ism/input_limits.hpp"
#include "asr_ism/ism_learning.hpp"
#include "asr_ism_tree/star_partition.hpp"

namespace asr_ism_tree {

using asr_common::InputError;

namespace {

void requireSameObjects(const asr_ism::Demonstration& demonstration,
                        const RelationTopology& topology) {
  const std::string what = "scene '" + demonstration.scene() + "'";
  for (const ObjectKey& key : topology.objects()) {
    if (demonstration.indexOf(key) < 0) {
      throw InputError(what + ": the relation topology names " + key.toString() +
                       ", which the demonstration does not contain");
    }
  }
  for (const ObjectKey& key : demonstration.objects()) {
    if (topology.indexOf(key) < 0) {
      throw InputError(what + ": the relation topology leaves out demonstrated object " +
                       key.toString());
    }
  }
}

// The ISM index of each star: root 0, sub-ISM k at k + 1, k counting down in conversion order
// (deepest stars first, later extracted first within a height; the root last).
std::vector<int> ismIndexOfStars(const std::vector<Star>& stars) {
  std::vector<int> order(stars.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    if (stars[a].height != stars[b].height)
      return stars[a].height > stars[b].height;
    return a > b;
  });
  std::vector<int> ism_of_star(stars.size());
  for (std::size_t position = 0; position < order.size(); ++position)
    ism_of_star[order[position]] = static_cast<int>(order.size() - 1 - position);
  return ism_of_star;
}

// The members of star `s`'s ISM: its centre, then each neighbour, which is a placeholder for
// the child ISM whose star it centres, if any. A placeholder moves with the child ISM's
// reference: the child star's centre.
std::vector<asr_ism::MemberTrajectory> starMembers(const asr_ism::Demonstration& demonstration,
                                                   const RelationTopology& topology,
                                                   const std::vector<Star>& stars,
                                                   const std::vector<int>& ism_of_star,
                                                   std::size_t s) {
  const auto trajectory_of = [&](int object) {
    return demonstration.trajectory(demonstration.indexOf(topology.objects()[object]));
  };
  const Star& star = stars[s];
  std::vector<asr_ism::MemberTrajectory> members;
  members.push_back({topology.objects()[star.center], -1, trajectory_of(star.center)});
  for (int neighbour : star.neighbours) {
    int child_ism = -1;
    for (std::size_t child = 0; child < stars.size(); ++child) {
      if (stars[child].parent == static_cast<int>(s) && stars[child].center == neighbour)
        child_ism = ism_of_star[child];
    }
    const ObjectKey key =
        child_ism < 0
            ? topology.objects()[neighbour]
            : ObjectKey{demonstration.scene() + "_sub" + std::to_string(child_ism - 1), ""};
    members.push_back({key, child_ism, trajectory_of(neighbour)});
  }
  return members;
}

}  // namespace

IsmTree generateIsmTree(const asr_ism::Demonstration& demonstration,
                        const RelationTopology& topology,
                        const asr_ism::IsmRecognitionParameters& parameters, int root_center) {
  demonstration.validate("demonstration");
  requireSameObjects(demonstration, topology);
  asr_ism::checkRecognitionParameters(parameters, "scene '" + demonstration.scene() + "'");
  topology.requireConnected("scene '" + demonstration.scene() + "'");
  const std::vector<Star> stars = partitionIntoStars(topology, root_center);
  const std::vector<int> ism_of_star = ismIndexOfStars(stars);

  IsmTree tree;
  tree.scene = demonstration.scene();
  tree.topology = topology;
  tree.parameters = parameters;
  tree.isms.resize(stars.size());
  tree.parent.assign(stars.size(), -1);
  tree.level.assign(stars.size(), 0);
  for (std::size_t s = 0; s < stars.size(); ++s) {
    const Star& star = stars[s];
    const int ism = ism_of_star[s];
    const std::string name = ism == 0 ? tree.scene : tree.scene + "_sub" + std::to_string(ism - 1);
    const ObjectKey& center_key = topology.objects()[star.center];
    const auto center_trajectory = demonstration.trajectory(demonstration.indexOf(center_key));
    tree.isms[ism] = asr_ism::learnIsm(name, center_key, center_trajectory,
                                       starMembers(demonstration, topology, stars, ism_of_star, s));
    tree.parent[ism] = star.parent < 0 ? -1 : ism_of_star[star.parent];
    tree.level[ism] = star.height;
  }
  tree.validate("generated tree");
  return tree;
}

}  // namespace asr_ism_tree
