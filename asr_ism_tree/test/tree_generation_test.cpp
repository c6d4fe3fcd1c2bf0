#include "asr_ism_tree/tree_generation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "asr_common/input_error.hpp"
#include "golden_graphs.hpp"
#include "synthetic_scene.hpp"

namespace asr_ism_tree {
namespace {

using asr_common::InputError;
using asr_common::Pose;

struct ExpectedMember {
  std::string object;  // ObjectKey::toString(): "A:1", or a child ISM's name
  int child_ism;
};

struct ExpectedIsm {
  std::string name;
  std::string reference;
  std::vector<ExpectedMember> members;
  int parent;
  int level;
};

struct ExpectedTree {
  std::vector<ExpectedIsm> isms;
  int height;
  std::size_t leaves;
};

void expectTree(const IsmTree& tree, const ExpectedTree& expected) {
  ASSERT_EQ(tree.isms.size(), expected.isms.size());
  ASSERT_EQ(tree.parent.size(), expected.isms.size());
  ASSERT_EQ(tree.level.size(), expected.isms.size());
  for (std::size_t i = 0; i < expected.isms.size(); ++i) {
    SCOPED_TRACE("ISM " + std::to_string(i));
    const asr_ism::Ism& ism = tree.isms[i];
    const ExpectedIsm& want = expected.isms[i];
    EXPECT_EQ(ism.name, want.name);
    EXPECT_EQ(ism.reference.toString(), want.reference);
    EXPECT_EQ(tree.parent[i], want.parent);
    EXPECT_EQ(tree.level[i], want.level);
    EXPECT_EQ(tree.indexOf(want.name), static_cast<int>(i));
    ASSERT_EQ(ism.members.size(), want.members.size());
    for (std::size_t m = 0; m < want.members.size(); ++m) {
      EXPECT_EQ(ism.members[m].object.toString(), want.members[m].object) << "member " << m;
      EXPECT_EQ(ism.members[m].child_ism, want.members[m].child_ism) << "member " << m;
      if (want.members[m].child_ism >= 0) {
        EXPECT_EQ(tree.placeholderMemberInParent(want.members[m].child_ism), static_cast<int>(m));
      }
    }
    // The reference is the first member and votes with the identity.
    EXPECT_EQ(ism.members[0].object, ism.reference);
    ASSERT_FALSE(ism.members[0].relative_poses.empty());
    EXPECT_TRUE(asr_common::approximatelyEqual(ism.members[0].relative_poses[0].reference_in_member,
                                               Pose::identity(), 1e-12, 1e-12));
  }
  EXPECT_EQ(tree.height(), expected.height);
  EXPECT_EQ(tree.leafCount(), expected.leaves);
  EXPECT_NO_THROW(tree.validate("test"));
}

// Each member's relative poses must be exactly the reference seen from the object the member
// stands for (a placeholder moves with its child ISM's reference), one per demonstrated step.
void expectRelativePosesFromTheDemonstration(const IsmTree& tree,
                                             const asr_ism::Demonstration& demonstration) {
  for (const asr_ism::Ism& ism : tree.isms) {
    const int reference = demonstration.indexOf(ism.reference);
    ASSERT_GE(reference, 0);
    for (const asr_ism::IsmMember& member : ism.members) {
      const asr_common::ObjectKey& stands_for =
          member.isPlaceholder() ? tree.isms[member.child_ism].reference : member.object;
      const int object = demonstration.indexOf(stands_for);
      ASSERT_GE(object, 0) << stands_for.toString();
      std::uint32_t steps = 0;
      for (const asr_ism::RelativePose& relative : member.relative_poses)
        steps += relative.step_count;
      EXPECT_EQ(steps, demonstration.stepCount()) << ism.name << " / " << member.object.toString();
      for (std::size_t step = 0; step < demonstration.stepCount(); ++step) {
        const Pose expected = asr_common::relativePose(*demonstration.pose(step, object),
                                                       *demonstration.pose(step, reference));
        const bool found = std::any_of(member.relative_poses.begin(), member.relative_poses.end(),
                                       [&](const auto& relative) {
                                         return asr_common::approximatelyEqual(
                                             relative.reference_in_member, expected, 1e-9, 1e-9);
                                       });
        EXPECT_TRUE(found) << ism.name << " / " << member.object.toString() << ", step " << step;
      }
    }
  }
}

IsmTree generate(const std::string& scene, const RelationTopology& topology, int root = -1) {
  const auto demonstration = synthetic::demonstration(scene, topology.objects());
  IsmTree tree = generateIsmTree(demonstration, topology, {}, root);
  expectRelativePosesFromTheDemonstration(tree, demonstration);
  return tree;
}

TEST(TreeGeneration, Chain) {
  // Stars: B {A, C} (root), C {D} below it. C's ISM replaces C in the root.
  const IsmTree tree = generate("chain", golden::chain());
  expectTree(tree, {{{"chain", "B:1", {{"B:1", -1}, {"A:1", -1}, {"chain_sub0", 1}}, -1, 0},
                     {"chain_sub0", "C:1", {{"C:1", -1}, {"D:1", -1}}, 0, 1}},
                    2,
                    4});
  EXPECT_EQ(tree.scene, "chain");
  EXPECT_EQ(tree.topology, golden::chain());
}

TEST(TreeGeneration, ChainFromAGivenRootIsThreeLevelsDeep) {
  // Stars A {B}, B {C}, C {D}: the deepest is converted first and becomes sub1.
  const IsmTree tree = generate("chain", golden::chain(), 0);
  expectTree(tree, {{{"chain", "A:1", {{"A:1", -1}, {"chain_sub0", 1}}, -1, 0},
                     {"chain_sub0", "B:1", {{"B:1", -1}, {"chain_sub1", 2}}, 0, 1},
                     {"chain_sub1", "C:1", {{"C:1", -1}, {"D:1", -1}}, 1, 2}},
                    3,
                    4});
}

TEST(TreeGeneration, Triangle) {
  const IsmTree tree = generate("triangle", golden::triangle());
  expectTree(tree, {{{"triangle", "A:1", {{"A:1", -1}, {"triangle_sub0", 1}, {"C:1", -1}}, -1, 0},
                     {"triangle_sub0", "B:1", {{"B:1", -1}, {"C:1", -1}}, 0, 1}},
                    2,
                    4});
}

TEST(TreeGeneration, CompleteGraphOfFour) {
  // Stars A {B, C, D} (root), B {C, D}, C {D}, both below the root. Conversion: C's star first
  // (later extracted), named sub1; B's star sub0. Leaves: A, D + B, C, D + C, D.
  const IsmTree tree = generate("complete", golden::complete4());
  expectTree(tree, {{{"complete",
                      "A:1",
                      {{"A:1", -1}, {"complete_sub0", 1}, {"complete_sub1", 2}, {"D:1", -1}},
                      -1,
                      0},
                     {"complete_sub0", "B:1", {{"B:1", -1}, {"C:1", -1}, {"D:1", -1}}, 0, 1},
                     {"complete_sub1", "C:1", {{"C:1", -1}, {"D:1", -1}}, 0, 1}},
                    2,
                    7});
}

TEST(TreeGeneration, StarIsASingleIsm) {
  const IsmTree tree = generate("star", golden::starAroundC());
  expectTree(
      tree, {{{"star", "C:1", {{"C:1", -1}, {"A:1", -1}, {"B:1", -1}, {"D:1", -1}}, -1, 0}}, 1, 4});
}

TEST(TreeGeneration, BranchingGraph) {
  const IsmTree tree = generate("branching", golden::branching());
  expectTree(tree, {{{"branching",
                      "C:1",
                      {{"C:1", -1}, {"branching_sub0", 1}, {"D:1", -1}, {"E:1", -1}, {"F:1", -1}},
                      -1,
                      0},
                     {"branching_sub0", "A:1", {{"A:1", -1}, {"branching_sub1", 2}}, 0, 1},
                     {"branching_sub1", "B:1", {{"B:1", -1}, {"D:1", -1}}, 1, 2}},
                    3,
                    7});
}

TEST(TreeGeneration, SingleObject) {
  const IsmTree tree = generate("alone", RelationTopology(golden::lettered(1)));
  expectTree(tree, {{{"alone", "A:1", {{"A:1", -1}}, -1, 0}}, 1, 1});
}

TEST(TreeGeneration, TopologyObjectOrderMayDifferFromTheDemonstration) {
  // Same triangle, objects listed C, B, A: the stars follow the topology's indices (root C), the
  // trajectories are found by key.
  std::vector<asr_common::ObjectKey> reversed = golden::lettered(3);
  std::reverse(reversed.begin(), reversed.end());
  const auto demonstration = synthetic::demonstration("triangle", golden::lettered(3));
  const IsmTree tree = generateIsmTree(demonstration, RelationTopology::complete(reversed), {});
  expectRelativePosesFromTheDemonstration(tree, demonstration);
  expectTree(tree, {{{"triangle", "C:1", {{"C:1", -1}, {"triangle_sub0", 1}, {"A:1", -1}}, -1, 0},
                     {"triangle_sub0", "B:1", {{"B:1", -1}, {"A:1", -1}}, 0, 1}},
                    2,
                    4});
  EXPECT_EQ(tree.objects(), reversed);
}

TEST(TreeGeneration, StoresTheParameters) {
  asr_ism::IsmRecognitionParameters parameters;
  parameters.bin_size = 0.07;
  parameters.max_angle_deviation = 0.2;
  const auto demonstration = synthetic::demonstration("chain", golden::lettered(4));
  const IsmTree tree = generateIsmTree(demonstration, golden::chain(), parameters);
  EXPECT_EQ(tree.parameters.bin_size, 0.07);
  EXPECT_EQ(tree.parameters.max_angle_deviation, 0.2);
  asr_ism::IsmRecognitionParameters bad;
  bad.bin_size = -1.0;
  EXPECT_THROW(generateIsmTree(demonstration, golden::chain(), bad), InputError);
}

TEST(TreeGeneration, DisconnectedTopologyIsAnError) {
  RelationTopology topology = golden::chain();
  topology.removeRelation(2, 3);
  const auto demonstration = synthetic::demonstration("chain", golden::lettered(4));
  try {
    generateIsmTree(demonstration, topology, {});
    FAIL() << "no InputError thrown";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("D:1"), std::string::npos) << error.what();
  }
}

TEST(TreeGeneration, TopologyNamingAnUnknownObjectIsAnError) {
  std::vector<asr_common::ObjectKey> keys = golden::lettered(3);
  keys.push_back({"Teapot", "9"});
  const auto demonstration = synthetic::demonstration("scene", golden::lettered(3));
  try {
    generateIsmTree(demonstration, RelationTopology::complete(keys), {});
    FAIL() << "no InputError thrown";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("Teapot:9"), std::string::npos) << error.what();
  }
}

TEST(TreeGeneration, TopologyLeavingOutADemonstratedObjectIsAnError) {
  const auto demonstration = synthetic::demonstration("scene", golden::lettered(4));
  try {
    generateIsmTree(demonstration, RelationTopology::complete(golden::lettered(3)), {});
    FAIL() << "no InputError thrown";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("D:1"), std::string::npos) << error.what();
  }
}

TEST(TreeGeneration, ObjectNeverObservedIsAnError) {
  asr_ism::Demonstration demonstration("scene", golden::lettered(2));
  demonstration.addStep();
  demonstration.setPose(0, 0, Pose::identity());
  EXPECT_THROW(generateIsmTree(demonstration, golden::withRelations(2, {{0, 1}}), {}), InputError);
}

TEST(TreeGeneration, ObjectsObservedOnlyApartCannotBeRelated) {
  // A and B never share a time step: the relation between them cannot be learned.
  asr_ism::Demonstration demonstration("scene", golden::lettered(2));
  demonstration.addStep();
  demonstration.addStep();
  demonstration.setPose(0, 0, Pose::identity());
  demonstration.setPose(1, 1, Pose::identity());
  EXPECT_THROW(generateIsmTree(demonstration, golden::withRelations(2, {{0, 1}}), {}), InputError);
}

TEST(IsmTree, ValidateDetectsBrokenLinks) {
  const auto demonstration = synthetic::demonstration("chain", golden::lettered(4));
  const IsmTree tree = generateIsmTree(demonstration, golden::chain(), {});
  IsmTree broken_child = tree;
  broken_child.isms[0].members[2].child_ism = 5;
  EXPECT_THROW(broken_child.validate("edited"), InputError);
  IsmTree broken_level = tree;
  broken_level.level[1] = 2;
  EXPECT_THROW(broken_level.validate("edited"), InputError);
  IsmTree unknown_object = tree;
  unknown_object.isms[1].members[1].object = {"Teapot", "9"};
  EXPECT_THROW(unknown_object.validate("edited"), InputError);
  IsmTree orphan = tree;
  orphan.isms[0].members[2].child_ism = -1;
  EXPECT_THROW(orphan.validate("edited"), InputError);
}

}  // namespace
}  // namespace asr_ism_tree
