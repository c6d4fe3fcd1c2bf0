#include "benchmark_trees.hpp"

#include "asr_ism_tree/star_center.hpp"
#include "asr_ism_tree/tree_generation.hpp"

namespace asr_pose_prediction::bench {

std::vector<BenchmarkTree> learnStarAndComplete(const asr_ism::Demonstration& demonstration) {
  using asr_ism_tree::RelationTopology;
  const auto& objects = demonstration.objects();
  const RelationTopology star =
      RelationTopology::star(objects, asr_ism_tree::chooseStarCenter(demonstration));
  return {{"star", asr_ism_tree::generateIsmTree(demonstration, star, {})},
          {"complete",
           asr_ism_tree::generateIsmTree(demonstration, RelationTopology::complete(objects), {})}};
}

}  // namespace asr_pose_prediction::bench
