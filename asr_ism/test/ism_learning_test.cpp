#include "asr_ism/ism_learning.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "asr_common/testing/input_error_of.hpp"

namespace asr_ism {
namespace {

Pose makePose(double x, double y, double z, double angle, const Eigen::Vector3d& axis) {
  return Pose(Eigen::Vector3d(x, y, z), Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis)));
}

using asr_common::testing::inputErrorOf;

const ObjectKey kReference{"Plate", "1"};
const ObjectKey kCup{"Cup", "7"};

TEST(IsmLearning, OneRelativePosePerStepWithMemberAndReference) {
  // The reference is absent in step 1, the cup in step 2: only steps 0 and 3 relate them.
  const Trajectory reference = {makePose(1.0, 2.0, 0.7, 0.3, Eigen::Vector3d::UnitZ()),
                                {},
                                makePose(1.1, 2.0, 0.7, 0.2, Eigen::Vector3d::UnitZ()),
                                makePose(0.4, -1.0, 0.8, -1.2, Eigen::Vector3d::UnitZ())};
  const Trajectory cup = {makePose(1.3, 2.1, 0.75, 0.0, Eigen::Vector3d::UnitZ()),
                          makePose(1.3, 2.2, 0.75, 0.0, Eigen::Vector3d::UnitZ()),
                          {},
                          makePose(0.5, -0.8, 0.9, 0.4, Eigen::Vector3d::UnitX())};
  const Ism ism = learnIsm("setting", kReference, reference, {{kCup, -1, cup}});

  EXPECT_EQ(ism.name, "setting");
  EXPECT_EQ(ism.reference, kReference);
  ASSERT_EQ(ism.members.size(), 1u);
  const IsmMember& member = ism.members[0];
  EXPECT_EQ(member.object, kCup);
  EXPECT_FALSE(member.isPlaceholder());
  ASSERT_EQ(member.relative_poses.size(), 2u);
  EXPECT_EQ(ism.relativePoseCount(), 2u);

  // Each stored pose is the reference seen from the cup in one of the two shared steps (the
  // storage order is not part of the contract).
  for (std::size_t step : {0u, 3u}) {
    const Pose expected = relativePose(*cup[step], *reference[step]);
    int found = 0;
    for (const RelativePose& relative : member.relative_poses) {
      if (approximatelyEqual(relative.reference_in_member, expected, 1e-12, 1e-12)) {
        ++found;
        EXPECT_EQ(relative.step_count, 1u);
      }
    }
    EXPECT_EQ(found, 1) << "step " << step;
  }
  // The relative pose is what a vote needs: member pose * relative pose = reference pose.
  for (const RelativePose& relative : member.relative_poses) {
    const bool from_step_0 = approximatelyEqual(compose(*cup[0], relative.reference_in_member),
                                                *reference[0], 1e-12, 1e-12);
    const bool from_step_3 = approximatelyEqual(compose(*cup[3], relative.reference_in_member),
                                                *reference[3], 1e-12, 1e-12);
    EXPECT_TRUE(from_step_0 || from_step_3);
  }
}

TEST(IsmLearning, ReferenceAsItsOwnMemberVotesWithTheIdentity) {
  const Trajectory reference = {
      makePose(1.0, 2.0, 0.7, 0.3, Eigen::Vector3d::UnitZ()),
      makePose(-3.0, 0.5, 0.1, 2.0, Eigen::Vector3d(1, 1, 0).normalized()),
      {},
      makePose(0.2, 0.2, 0.2, -0.4, Eigen::Vector3d::UnitY())};
  const Ism ism = learnIsm("setting", kReference, reference, {{kReference, -1, reference}});
  ASSERT_EQ(ism.members.size(), 1u);
  // Three observed steps, all with the identity (up to rounding): one pose counted three times.
  ASSERT_EQ(ism.members[0].relative_poses.size(), 1u);
  EXPECT_EQ(ism.members[0].relative_poses[0].step_count, 3u);
  EXPECT_TRUE(approximatelyEqual(ism.members[0].relative_poses[0].reference_in_member,
                                 Pose::identity(), 1e-12, 1e-12));
}

TEST(IsmLearning, EqualRelativePosesAreMergedWithTheirStepCount) {
  // The pair moves rigidly in steps 0, 1 and 3 (same relative pose at different places); in step
  // 2 the cup is 1e-6 m off, far above the merge tolerance, so that pose stays separate.
  const Pose cup_in_reference = makePose(0.25, -0.1, 0.05, 0.6, Eigen::Vector3d::UnitZ());
  const Pose places[] = {makePose(1.0, 2.0, 0.7, 0.3, Eigen::Vector3d::UnitZ()),
                         makePose(-2.0, 0.5, 0.7, 2.5, Eigen::Vector3d::UnitZ()),
                         makePose(0.0, 0.0, 0.7, 0.0, Eigen::Vector3d::UnitZ()),
                         makePose(3.0, 3.0, 0.0, 1.0, Eigen::Vector3d(1, 2, 3).normalized())};
  Trajectory reference, cup;
  for (int step = 0; step < 4; ++step) {
    reference.push_back(places[step]);
    Pose cup_pose = compose(places[step], cup_in_reference);
    if (step == 2)
      cup_pose.position.x() += 1e-6;
    cup.push_back(cup_pose);
  }
  const Ism ism = learnIsm("setting", kReference, reference, {{kCup, -1, cup}});
  ASSERT_EQ(ism.members.size(), 1u);
  const auto& relative_poses = ism.members[0].relative_poses;
  ASSERT_EQ(relative_poses.size(), 2u);
  std::uint32_t total_steps = 0;
  bool found_merged = false;
  for (const RelativePose& relative : relative_poses) {
    total_steps += relative.step_count;
    if (relative.step_count == 3u) {
      found_merged = true;
      EXPECT_TRUE(
          approximatelyEqual(relative.reference_in_member, inverse(cup_in_reference), 1e-9, 1e-9));
    }
  }
  EXPECT_TRUE(found_merged);
  EXPECT_EQ(total_steps, 4u);
}

TEST(IsmLearning, PlaceholderMembersKeepTheirChildLink) {
  const Trajectory reference = {makePose(0, 0, 0, 0, Eigen::Vector3d::UnitZ())};
  const Trajectory child_center = {makePose(0.3, 0, 0, 0, Eigen::Vector3d::UnitZ())};
  const Ism ism = learnIsm("scene", kReference, reference,
                           {{kReference, -1, reference}, {{"scene_sub0", ""}, 1, child_center}});
  ASSERT_EQ(ism.members.size(), 2u);
  EXPECT_FALSE(ism.members[0].isPlaceholder());
  EXPECT_TRUE(ism.members[1].isPlaceholder());
  EXPECT_EQ(ism.members[1].child_ism, 1);
  EXPECT_EQ(ism.members[1].object, (ObjectKey{"scene_sub0", ""}));
}

TEST(IsmLearning, MemberThatNeverCoOccursWithTheReferenceIsAnError) {
  const Trajectory reference = {makePose(0, 0, 0, 0, Eigen::Vector3d::UnitZ()), {}};
  const Trajectory cup = {{}, makePose(1, 0, 0, 0, Eigen::Vector3d::UnitZ())};
  const std::string message = inputErrorOf([&] {
    learnIsm("setting", kReference, reference, {{kCup, -1, cup}});
  });
  EXPECT_NE(message.find("Cup:7"), std::string::npos) << message;
  EXPECT_NE(message.find("setting"), std::string::npos) << message;
}

TEST(IsmLearning, TrajectoriesOfDifferentLengthAreAnError) {
  const Trajectory reference = {makePose(0, 0, 0, 0, Eigen::Vector3d::UnitZ()),
                                makePose(0, 0, 0, 0, Eigen::Vector3d::UnitZ())};
  const Trajectory cup = {makePose(1, 0, 0, 0, Eigen::Vector3d::UnitZ())};
  const std::string message = inputErrorOf([&] {
    learnIsm("setting", kReference, reference, {{kCup, -1, cup}});
  });
  EXPECT_NE(message.find("Cup:7"), std::string::npos) << message;
}

}  // namespace
}  // namespace asr_ism
