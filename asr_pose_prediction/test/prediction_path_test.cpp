// Shortest prediction paths on trees whose shapes asr_ism_tree's tree_generation_test works out
// by hand (objects A, B, C, ... are object_0, object_1, object_2, ... here).

#include "asr_pose_prediction/prediction_path.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "asr_common/testing/input_error_of.hpp"
#include "asr_ism/synthetic_demonstration.hpp"
#include "asr_ism_tree/tree_generation.hpp"

namespace asr_pose_prediction {
namespace {

using asr_ism_tree::RelationTopology;

// A path as "ism:member > ism:member", ISMs by name, members by the object they stand for.
std::string describe(const IsmTree& tree, const PredictionPath& path) {
  std::string text;
  for (const PredictionStep& step : path.steps) {
    const asr_ism::Ism& ism = tree.isms[step.ism];
    text +=
        (text.empty() ? "" : " > ") + ism.name + ":" + ism.members[step.member].object.toString();
  }
  return text;
}

// The tree of `scene` over `count` synthetic objects with the relations `pairs`.
IsmTree treeOf(const std::string& scene, int count, const std::vector<std::pair<int, int>>& pairs,
               int root = -1) {
  const asr_ism::Demonstration demonstration =
      asr_ism::makeSyntheticDemonstration(count, 6, 3, scene);
  RelationTopology topology(demonstration.objects());
  for (const auto& [a, b] : pairs)
    topology.addRelation(a, b);
  return asr_ism_tree::generateIsmTree(demonstration, topology, {}, root);
}

void expectPaths(const IsmTree& tree, const std::vector<std::string>& expected) {
  const std::vector<PredictionPath> paths = shortestPredictionPaths(tree);
  ASSERT_EQ(paths.size(), expected.size());
  for (std::size_t object = 0; object < paths.size(); ++object) {
    EXPECT_EQ(paths[object].object, tree.objects()[object]);
    EXPECT_EQ(describe(tree, paths[object]), expected[object]) << "object " << object;
    // Every step but the last leads on through the placeholder of the next ISM.
    const auto& steps = paths[object].steps;
    ASSERT_FALSE(steps.empty());
    EXPECT_EQ(steps.front().ism, 0);
    for (std::size_t k = 0; k + 1 < steps.size(); ++k)
      EXPECT_EQ(tree.isms[steps[k].ism].members[steps[k].member].child_ism, steps[k + 1].ism);
    EXPECT_FALSE(tree.isms[steps.back().ism].members[steps.back().member].isPlaceholder());
  }
}

TEST(PredictionPath, StarTreeIsOneStepForEveryObject) {
  // C is the centre: one ISM whose members are C, A, B, D.
  const IsmTree tree = treeOf("star", 4, {{2, 0}, {2, 1}, {2, 3}});
  expectPaths(tree, {"star:object_0:0", "star:object_1:0", "star:object_2:0", "star:object_3:0"});
}

TEST(PredictionPath, ChainFromItsEndGoesDownEveryLevel) {
  // A {A, sub0}, sub0 = B {B, sub1}, sub1 = C {C, D}: C and D are leaves two levels down only.
  const IsmTree tree = treeOf("chain", 4, {{0, 1}, {1, 2}, {2, 3}}, 0);
  expectPaths(tree, {"chain:object_0:0", "chain:chain_sub0 > chain_sub0:object_1:0",
                     "chain:chain_sub0 > chain_sub0:chain_sub1 > chain_sub1:object_2:0",
                     "chain:chain_sub0 > chain_sub0:chain_sub1 > chain_sub1:object_3:0"});
  EXPECT_EQ(ismNames(tree, shortestPredictionPaths(tree)[3]),
            (std::vector<std::string>{"chain", "chain_sub0", "chain_sub1"}));
}

TEST(PredictionPath, CompleteGraphUsesTheShallowerLeafAndBreaksTiesByMemberOrder) {
  // Root A {A, sub0, sub1, D}, sub0 = B {B, C, D}, sub1 = C {C, D}. D is a leaf of the root and
  // of both sub-ISMs: the root's leaf is used. C is a leaf of sub0 and sub1, both one level
  // down: sub0's placeholder comes first in the root, so sub0 is used.
  const IsmTree tree = treeOf("complete", 4, {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}});
  expectPaths(tree, {"complete:object_0:0", "complete:complete_sub0 > complete_sub0:object_1:0",
                     "complete:complete_sub0 > complete_sub0:object_2:0", "complete:object_3:0"});
}

TEST(PredictionPath, LeafTwoLevelsApartUsesTheUpperOne) {
  // Root C {C, sub0, D, E, F}, sub0 = A {A, sub1}, sub1 = B {B, D}: D is a leaf at levels 0 and 2.
  const IsmTree tree = treeOf("branching", 6, {{0, 1}, {0, 2}, {1, 3}, {2, 3}, {2, 4}, {2, 5}});
  ASSERT_EQ(tree.height(), 3);
  expectPaths(tree, {"branching:branching_sub0 > branching_sub0:object_0:0",
                     "branching:branching_sub0 > branching_sub0:branching_sub1 > "
                     "branching_sub1:object_1:0",
                     "branching:object_2:0", "branching:object_3:0", "branching:object_4:0",
                     "branching:object_5:0"});
}

TEST(PredictionPath, AnObjectWithoutALeafIsNamed) {
  IsmTree tree = treeOf("chain", 4, {{0, 1}, {1, 2}, {2, 3}}, 0);
  // Drop D, the last member of the deepest ISM: the tree still links up, but D has no leaf.
  auto& deepest = tree.isms[2].members;
  ASSERT_EQ(deepest.back().object.toString(), "object_3:0");
  deepest.pop_back();
  const std::string message =
      asr_common::testing::inputErrorOf([&] { shortestPredictionPaths(tree); });
  EXPECT_NE(message.find("object_3:0"), std::string::npos) << message;
  EXPECT_NE(message.find("chain"), std::string::npos) << message;
}

}  // namespace
}  // namespace asr_pose_prediction
