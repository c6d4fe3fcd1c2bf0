// The random parts of prediction: draws weighted by step count, unbiased integers, and the split
// of a pose budget among instances by confidence.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "asr_common/testing/input_error_of.hpp"
#include "asr_ism/portable_random.hpp"
#include "asr_pose_prediction/confidence_split.hpp"
#include "asr_pose_prediction/relation_sampler.hpp"

namespace asr_pose_prediction {
namespace {

using asr_common::testing::inputErrorOf;

asr_ism::RelativePose relative(double x, std::uint32_t steps) {
  asr_ism::RelativePose pose;
  pose.reference_in_member =
      asr_common::Pose(Eigen::Vector3d(x, 0, 0), Eigen::Quaterniond::Identity());
  pose.step_count = steps;
  return pose;
}

TEST(UniformBelow, StaysBelowTheBoundAndReachesEveryValue) {
  std::mt19937 engine(3);
  std::vector<int> seen(7, 0);
  for (int i = 0; i < 7000; ++i) {
    const std::uint32_t value = asr_ism::uniformBelow(engine, 7);
    ASSERT_LT(value, 7u);
    ++seen[value];
  }
  for (int count : seen)
    EXPECT_NEAR(count, 1000, 150);
  EXPECT_EQ(asr_ism::uniformBelow(engine, 1), 0u);
}

TEST(RelationSampler, DrawsRelativePosesInProportionToTheirStepCounts) {
  asr_ism::IsmMember member;
  member.object = {"Cup", "0"};
  member.relative_poses = {relative(1.0, 1), relative(2.0, 3)};
  const RelationSampler sampler(member, "member Cup:0");
  ASSERT_EQ(sampler.size(), 2u);
  // The sampler hands out the member seen from the reference: the inverse of reference_in_member.
  EXPECT_NEAR(sampler.pose(0).position.x(), -1.0, 1e-12);

  std::mt19937 engine(11);
  int heavy = 0;
  for (int i = 0; i < 8000; ++i)
    heavy += sampler.sample(engine).position.x() == -2.0;
  EXPECT_NEAR(heavy / 8000.0, 0.75, 0.03);
}

TEST(RelationSampler, RefusesAMemberWithoutRelativePoses) {
  asr_ism::IsmMember member;
  member.object = {"Cup", "0"};
  const std::string message = inputErrorOf([&] { RelationSampler(member, "member Cup:0"); });
  EXPECT_NE(message.find("Cup:0"), std::string::npos) << message;
}

TEST(SplitByConfidence, AddsUpAndFollowsTheConfidences) {
  EXPECT_EQ(splitByConfidence(100, {0.9, 0.6}), (std::vector<std::size_t>{60, 40}));
  EXPECT_EQ(splitByConfidence(10, {1.0, 1.0, 1.0}), (std::vector<std::size_t>{4, 3, 3}));
  EXPECT_EQ(splitByConfidence(5, {0.0, 0.0}), (std::vector<std::size_t>{3, 2}));
  EXPECT_EQ(splitByConfidence(7, {1.0}), (std::vector<std::size_t>{7}));
  EXPECT_TRUE(splitByConfidence(7, {}).empty());
}

TEST(SplitByConfidence, RefusesNegativeOrNonFiniteConfidences) {
  EXPECT_NE(inputErrorOf([] {
              splitByConfidence(10, {0.5, -0.1});
            }).find("confidence"),
            std::string::npos);
  EXPECT_NE(inputErrorOf([] { splitByConfidence(10, {NAN}); }).find("confidence"),
            std::string::npos);
}

}  // namespace
}  // namespace asr_pose_prediction
