#include "asr_ism/ism_recognizer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

#include "asr_ism/common_types.hpp"
#include "asr_ism/compliance.hpp"
#include "asr_ism/portable_random.hpp"
#include "asr_ism/voting_space.hpp"

namespace asr_ism {
namespace {

constexpr double kDegree = M_PI / 180.0;

Pose makePose(double x, double y, double z, double angle = 0.0,
              const Eigen::Vector3d& axis = Eigen::Vector3d::UnitZ()) {
  return Pose(Eigen::Vector3d(x, y, z), Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis)));
}

// A hand-made ISM of three members: the reference R (voting with the identity), A one 0.25 m
// below it (so turning A about its own z axis changes only the orientation of its vote) and B
// beside it, turned by 90 degrees.
enum Member { kR = 0, kA = 1, kB = 2 };

Ism threeMemberIsm() {
  Ism ism;
  ism.name = "hand_made";
  ism.reference = {"R", ""};
  ism.members = {{{"R", ""}, -1, {{Pose::identity(), 1}}},
                 {{"A", ""}, -1, {{makePose(0.0, 0.0, 0.25), 1}}},
                 {{"B", ""}, -1, {{makePose(-0.3, 0.1, 0.0, M_PI / 2), 1}}}};
  return ism;
}

// Where a member stands when the reference is at `reference`: reference * inverse(relative pose).
Pose memberPose(const Ism& ism, int member, const Pose& reference, std::size_t relative = 0) {
  return compose(reference,
                 inverse(ism.members[member].relative_poses[relative].reference_in_member));
}

// A reference pose away from bin borders and with a turn, so nothing is axis-aligned by luck.
const Pose kScene = makePose(1.03, 2.04, 0.77, 0.4, Eigen::Vector3d::UnitZ());

std::vector<IsmInput> perfectInputs(const Ism& ism, const Pose& reference = kScene) {
  std::vector<IsmInput> inputs;
  for (int m = 0; m < static_cast<int>(ism.members.size()); ++m)
    inputs.push_back({m, memberPose(ism, m, reference), 1.0, {}});
  return inputs;
}

Pose movedBy(const Pose& pose, const Eigen::Vector3d& shift) {
  return Pose(pose.position + shift, pose.orientation);
}

Pose turnedAboutOwnZ(const Pose& pose, double angle) {
  return Pose(pose.position, pose.orientation * Eigen::Quaterniond(Eigen::AngleAxisd(
                                                    angle, Eigen::Vector3d::UnitZ())));
}

TEST(IsmRecognizer, PerfectConfigurationMatchesEveryMemberFully) {
  const Ism ism = threeMemberIsm();
  const auto results = recognizeIsm(ism, perfectInputs(ism), {});
  ASSERT_FALSE(results.empty());
  const IsmResult& best = results[0];
  EXPECT_NEAR(best.objective, 3.0, 1e-9);
  ASSERT_EQ(best.matches.size(), 3u);
  for (int m = 0; m < 3; ++m) {
    EXPECT_EQ(best.matches[m].input, m);
    EXPECT_EQ(best.matches[m].relative_pose, 0);
    EXPECT_NEAR(best.matches[m].position_compliance, 1.0, 1e-9);
    EXPECT_NEAR(best.matches[m].orientation_compliance, 1.0, 1e-9);
  }
  EXPECT_TRUE(approximatelyEqual(best.reference_pose, kScene, 1e-9, 1e-9));
  // The one consistent combination is reported once.
  EXPECT_EQ(results.size(), 1u);
}

// The support radius of bins of 0.1 m: half their diagonal.
const double kRadius = std::sqrt(3.0) / 2.0 * 0.1;

TEST(IsmRecognizer, ObjectMovedBeyondTheSupportRadiusIsUnmatched) {
  const Ism ism = threeMemberIsm();
  const IsmRecognitionParameters parameters;  // bin 0.1 m
  EXPECT_NEAR(parameters.supportRadius(), kRadius, 1e-15);
  for (double shift : {0.0867, 0.1, 0.15, 0.3}) {
    auto inputs = perfectInputs(ism);
    inputs[kA].pose = movedBy(inputs[kA].pose, Eigen::Vector3d(shift, 0.0, 0.0));
    const auto results = recognizeIsm(ism, inputs, parameters);
    ASSERT_FALSE(results.empty());
    EXPECT_FALSE(results[0].matches[kA].matched()) << shift;
    EXPECT_EQ(results[0].matches[kA].similarity(), 0.0) << shift;
    EXPECT_NEAR(results[0].objective, 2.0, 1e-9) << shift;
  }
  // Just inside the radius it still counts, barely.
  auto inputs = perfectInputs(ism);
  inputs[kA].pose = movedBy(inputs[kA].pose, Eigen::Vector3d(0.086, 0.0, 0.0));
  const auto results = recognizeIsm(ism, inputs, parameters);
  ASSERT_TRUE(results[0].matches[kA].matched());
  EXPECT_NEAR(results[0].matches[kA].position_compliance,
              1.0 - (0.086 / kRadius) * (0.086 / kRadius), 1e-9);
}

// The support test holds at the object too. In a scene metres wide (L 3 m from the reference R,
// B 2 m), L moved 0.2 m sideways and turned by 3.8 deg casts its vote within 7 mm and 3.8 deg
// of the reference, so a hypothesis taken from L's vote passes R's and B's votes too. Carried
// back through B's relation, that turned hypothesis puts B 13 cm from where it is, and the
// hypothesis at R puts L 0.2 m from where it is: L cannot count with both others.
TEST(IsmRecognizer, ObjectOffItsPlaceDoesNotCountEvenIfItsVoteHitsTheReference) {
  Ism ism;
  ism.name = "long_relations";
  ism.reference = {"R", ""};
  ism.members = {{{"R", ""}, -1, {{Pose::identity(), 1}}},
                 {{"L", ""}, -1, {{makePose(3.0, 0.0, 0.0), 1}}},
                 {{"B", ""}, -1, {{makePose(0.0, -2.0, 0.0), 1}}}};
  const std::vector<IsmInput> exact = {{0, makePose(3.0, 0.0, 0.0), 1.0, {}},
                                       {1, Pose::identity(), 1.0, {}},
                                       {2, makePose(3.0, 2.0, 0.0), 1.0, {}}};
  ASSERT_NEAR(recognizeIsm(ism, exact, {})[0].objective, 3.0, 1e-12);

  std::vector<IsmInput> inputs = exact;
  inputs[1].pose = makePose(0.0, 0.2, 0.0, -std::asin(0.2 / 3.0));
  const Pose vote = compose(inputs[1].pose, ism.members[1].relative_poses[0].reference_in_member);
  ASSERT_LT((vote.position - exact[0].pose.position).norm(), 0.007);
  auto results = recognizeIsm(ism, inputs, {});
  ASSERT_FALSE(results.empty());
  EXPECT_FALSE(results[0].matches[1].matched());
  EXPECT_NEAR(results[0].objective, 2.0, 1e-12);

  // Turned by 1 deg in place: its vote is 5.2 cm off, and so is the object carried back.
  inputs[1].pose = makePose(0.0, 0.0, 0.0, 1.0 * kDegree);
  results = recognizeIsm(ism, inputs, {});
  ASSERT_TRUE(results[0].matches[1].matched());
  const double off = 2.0 * 3.0 * std::sin(0.5 * kDegree);
  EXPECT_NEAR(results[0].matches[1].position_compliance, 1.0 - off * off / (kRadius * kRadius),
              1e-6);
  EXPECT_NEAR(results[0].objective, 2.0 + results[0].matches[1].similarity(), 1e-12);
}

TEST(IsmRecognizer, ObjectTurnedBeyondTheMaximumAngleIsUnmatched) {
  const Ism ism = threeMemberIsm();
  const IsmRecognitionParameters parameters;  // 30 degrees
  for (double degrees : {31.0, 45.0, 90.0, 180.0}) {
    auto inputs = perfectInputs(ism);
    inputs[kA].pose = turnedAboutOwnZ(inputs[kA].pose, degrees * kDegree);
    const auto results = recognizeIsm(ism, inputs, parameters);
    ASSERT_FALSE(results.empty());
    EXPECT_FALSE(results[0].matches[kA].matched()) << degrees;
    EXPECT_NEAR(results[0].objective, 2.0, 1e-9) << degrees;
  }
  auto inputs = perfectInputs(ism);
  inputs[kA].pose = turnedAboutOwnZ(inputs[kA].pose, 29.0 * kDegree);
  const auto results = recognizeIsm(ism, inputs, parameters);
  EXPECT_TRUE(results[0].matches[kA].matched());
  EXPECT_NEAR(results[0].matches[kA].position_compliance, 1.0, 1e-9);
}

TEST(IsmRecognizer, PositionComplianceAtHalfTheBinSize) {
  const Ism ism = threeMemberIsm();
  IsmRecognitionParameters parameters;
  parameters.bin_size = 0.2;
  auto inputs = perfectInputs(ism);
  // A diagonal shift of length 0.1 = half the bin size, against a radius of sqrt(3)/2 x 0.2:
  // 1 - d^2 / r^2 = 1 - 0.01 / 0.03 = 2/3.
  inputs[kA].pose = movedBy(inputs[kA].pose, Eigen::Vector3d(0.06, -0.08, 0.0));
  const auto results = recognizeIsm(ism, inputs, parameters);
  ASSERT_FALSE(results.empty());
  const MemberMatch& a = results[0].matches[kA];
  ASSERT_TRUE(a.matched());
  EXPECT_NEAR(a.position_compliance, 2.0 / 3.0, 1e-9);
  EXPECT_NEAR(a.orientation_compliance, 1.0, 1e-9);
  EXPECT_NEAR(a.similarity(), 2.0 / 3.0, 1e-9);
  EXPECT_NEAR(results[0].objective, 2.0 + 2.0 / 3.0, 1e-9);
  // The hypothesis is where R and B agree, not where A's vote is.
  EXPECT_TRUE(approximatelyEqual(results[0].reference_pose, kScene, 1e-9, 1e-9));
}

TEST(IsmRecognizer, OrientationComplianceAtHalfTheMaximumAngle) {
  const Ism ism = threeMemberIsm();
  IsmRecognitionParameters parameters;
  parameters.max_angle_deviation = 40.0 * kDegree;
  auto inputs = perfectInputs(ism);
  inputs[kA].pose = turnedAboutOwnZ(inputs[kA].pose, 20.0 * kDegree);
  const auto results = recognizeIsm(ism, inputs, parameters);
  ASSERT_FALSE(results.empty());
  const MemberMatch& a = results[0].matches[kA];
  ASSERT_TRUE(a.matched());
  // compliance.hpp: 1 - sin^2(theta / 2) / sin^2(theta_max / 2) ...
  const double expected =
      1.0 - std::pow(std::sin(10.0 * kDegree), 2) / std::pow(std::sin(20.0 * kDegree), 2);
  EXPECT_NEAR(a.orientation_compliance, expected, 1e-9);
  // ... which is close to 1 - (theta / theta_max)^2 = 0.75.
  EXPECT_NEAR(a.orientation_compliance, 0.75, 0.01);
  EXPECT_NEAR(a.position_compliance, 1.0, 1e-9);
  EXPECT_NEAR(results[0].objective, 2.0 + expected, 1e-9);
}

TEST(IsmRecognizer, InputWeightScalesTheContribution) {
  const Ism ism = threeMemberIsm();
  auto inputs = perfectInputs(ism);
  inputs[kB].weight = 2.5;  // as a placeholder standing for a child result of objective 2.5
  const auto results = recognizeIsm(ism, inputs, {});
  ASSERT_FALSE(results.empty());
  EXPECT_NEAR(results[0].objective, 4.5, 1e-9);
  EXPECT_NEAR(results[0].matches[kB].similarity(), 1.0, 1e-9);
}

TEST(IsmRecognizer, ClutterInputsDoNotRaiseTheObjective) {
  const Ism ism = threeMemberIsm();
  auto inputs = perfectInputs(ism);
  // Extra estimates of the members, all inconsistent with the scene at kScene: far away, near but
  // turned, and one of R placed where it would fit a different scene pose.
  inputs.push_back({kB, makePose(4.0, -3.0, 0.2), 1.0, {}});
  inputs.push_back({kA, turnedAboutOwnZ(inputs[kA].pose, 90.0 * kDegree), 1.0, {}});
  inputs.push_back({kR, movedBy(kScene, Eigen::Vector3d(0.5, 0.5, 0.0)), 1.0, {}});
  inputs.push_back({kB, movedBy(inputs[kB].pose, Eigen::Vector3d(0.0, 0.0, 0.3)), 1.0, {}});
  const auto results = recognizeIsm(ism, inputs, {});
  ASSERT_FALSE(results.empty());
  EXPECT_NEAR(results[0].objective, 3.0, 1e-9);
  for (const IsmResult& result : results)
    EXPECT_LE(result.objective, 3.0 + 1e-9);
  // The best result uses the three consistent inputs.
  for (int m = 0; m < 3; ++m)
    EXPECT_EQ(results[0].matches[m].input, m);
  for (std::size_t r = 1; r < results.size(); ++r)
    EXPECT_LT(results[r].objective, 2.0 + 1e-9);
}

TEST(IsmRecognizer, TwoInputsForOneMemberCountOnce) {
  const Ism ism = threeMemberIsm();
  auto inputs = perfectInputs(ism);
  inputs.push_back(inputs[kA]);  // an exact duplicate of A (index 3)
  auto results = recognizeIsm(ism, inputs, {});
  ASSERT_FALSE(results.empty());
  EXPECT_NEAR(results[0].objective, 3.0, 1e-9);
  EXPECT_TRUE(results[0].matches[kA].input == kA || results[0].matches[kA].input == 3);

  // A second A 2 cm off: the better one is used, the other adds nothing.
  inputs.back().pose = movedBy(inputs[kA].pose, Eigen::Vector3d(0.02, 0.0, 0.0));
  results = recognizeIsm(ism, inputs, {});
  ASSERT_FALSE(results.empty());
  EXPECT_NEAR(results[0].objective, 3.0, 1e-9);
  EXPECT_EQ(results[0].matches[kA].input, kA);
}

TEST(IsmRecognizer, BestCountCapsTheResults) {
  const Ism ism = threeMemberIsm();
  // Four copies of the scene 2 m apart; in copy k, A is off by shift[k], so copy k has objective
  // 2 + 1 - (shift[k] / r)^2. The ranks (2, 0, 3, 1) do not follow the copies' order in space,
  // so the search meets good results after worse ones.
  const double shifts[] = {0.04, 0.0, 0.06, 0.02};
  const int copy_of_rank[] = {1, 3, 0, 2};
  std::vector<IsmInput> inputs;
  for (int copy = 0; copy < 4; ++copy) {
    const Pose reference = movedBy(kScene, Eigen::Vector3d(2.0 * copy, 0.0, 0.0));
    auto copy_inputs = perfectInputs(ism, reference);
    copy_inputs[kA].pose = movedBy(copy_inputs[kA].pose, Eigen::Vector3d(0.0, shifts[copy], 0.0));
    inputs.insert(inputs.end(), copy_inputs.begin(), copy_inputs.end());
  }
  const auto all = recognizeIsm(ism, inputs, {}, IsmResultSelection{0});
  ASSERT_EQ(all.size(), 4u);
  for (int rank = 0; rank < 4; ++rank) {
    const int copy = copy_of_rank[rank];
    const double relative_shift = shifts[copy] / kRadius;
    EXPECT_NEAR(all[rank].objective, 3.0 - relative_shift * relative_shift, 1e-9) << rank;
    EXPECT_EQ(all[rank].matches[kR].input, 3 * copy);
  }
  for (std::size_t count : {1u, 2u, 3u}) {
    const auto capped = recognizeIsm(ism, inputs, {}, IsmResultSelection{count});
    ASSERT_EQ(capped.size(), count);
    for (std::size_t r = 0; r < count; ++r) {
      EXPECT_EQ(capped[r].objective, all[r].objective);
      EXPECT_EQ(capped[r].matches[kR].input, all[r].matches[kR].input);
    }
  }
  EXPECT_EQ(recognizeIsm(ism, inputs, {}, IsmResultSelection{10}).size(), 4u);
}

TEST(IsmRecognizer, ResultsUsingOnlyEstimatesOfABetterResultAreDropped) {
  Ism ism = threeMemberIsm();
  // A second relative pose of A sends a vote 1 m away, where it forms a result of A alone.
  ism.members[kA].relative_poses.push_back({makePose(1.0, 0.0, 0.25), 1});
  auto inputs = perfectInputs(ism);
  for (int i = 0; i < 3; ++i)
    inputs[i].estimates = {10 + i};
  const auto root = recognizeIsm(ism, inputs, {}, IsmResultSelection{0});
  ASSERT_EQ(root.size(), 1u);
  EXPECT_NEAR(root[0].objective, 3.0, 1e-9);
  EXPECT_EQ(root[0].estimates, (std::vector<int>{10, 11, 12}));

  // A sub-ISM passing results up drops it too while the better result is perfect: that one fits
  // every estimate fully, no other pose could serve a parent better.
  const auto sub = recognizeIsm(ism, inputs, {}, IsmResultSelection{4});
  ASSERT_EQ(sub.size(), 1u);
  EXPECT_EQ(sub[0].estimates, (std::vector<int>{10, 11, 12}));

  // With B 3 cm off, the better result is no longer perfect, and the sub-ISM passes the lone
  // result up as well: at another pose it is another placeholder for the parent. The root still
  // drops it.
  inputs[kB].pose = movedBy(inputs[kB].pose, Eigen::Vector3d(0.03, 0.0, 0.0));
  const auto imperfect = recognizeIsm(ism, inputs, {}, IsmResultSelection{4});
  ASSERT_EQ(imperfect.size(), 2u);
  EXPECT_EQ(imperfect[0].estimates, (std::vector<int>{10, 11, 12}));
  EXPECT_EQ(imperfect[1].estimates, (std::vector<int>{11}));
  EXPECT_EQ(recognizeIsm(ism, inputs, {}, IsmResultSelection{0}).size(), 1u);
}

TEST(IsmRecognizer, EarlierFoundResultIsDroppedWhenABetterOneUsesAllItsEstimates) {
  // Far from the scene, a heavy placeholder-like input of B (weight 2.5, standing for estimate 10,
  // which R's input stands for too) and a second vote of A 0.15 m beside it: their bins promise
  // 3.5, more than the scene's 3, so they are searched first, but they only reach 2.5 (B' alone)
  // and 1 (A' alone). The scene found afterwards uses estimates 10, 11 and 12: both earlier
  // results use only estimates of that better result and must not reach the root's answer.
  Ism ism = threeMemberIsm();
  auto inputs = perfectInputs(ism);
  for (int i = 0; i < 3; ++i)
    inputs[i].estimates = {10 + i};
  const Pose far_reference = movedBy(kScene, Eigen::Vector3d(2.0, 0.0, 0.0));
  inputs.push_back({kB, memberPose(ism, kB, far_reference), 2.5, {10}});
  ism.members[kA].relative_poses.push_back(
      {relativePose(inputs[kA].pose, movedBy(far_reference, Eigen::Vector3d(0.15, 0.0, 0.0))), 1});

  const auto root = recognizeIsm(ism, inputs, {}, IsmResultSelection{0});
  ASSERT_EQ(root.size(), 1u);
  EXPECT_NEAR(root[0].objective, 3.0, 1e-9);
  EXPECT_EQ(root[0].estimates, (std::vector<int>{10, 11, 12}));

  // A sub-ISM drops them as well (the scene's result is perfect), so they cannot take places under
  // its cap that a distinct hypothesis needs: a second copy of the scene 4 m away, with A and B
  // 6 cm off to opposite sides (best at R: 1 + 2 x (1 - 0.06^2 / r^2) = 1.04), is the second
  // result although both lone results score higher.
  const Pose second_reference = movedBy(kScene, Eigen::Vector3d(4.0, 0.0, 0.0));
  auto second_copy = perfectInputs(ism, second_reference);
  second_copy.resize(3);
  for (int i = 0; i < 3; ++i) {
    second_copy[i].estimates = {20 + i};
    if (i != kR) {
      const double side = i == kA ? 1.0 : -1.0;
      second_copy[i].pose = movedBy(second_copy[i].pose, Eigen::Vector3d(0.0, 0.06 * side, 0.0));
    }
  }
  inputs.insert(inputs.end(), second_copy.begin(), second_copy.end());
  const auto sub = recognizeIsm(ism, inputs, {}, IsmResultSelection{2});
  ASSERT_EQ(sub.size(), 2u);
  EXPECT_NEAR(sub[0].objective, 3.0, 1e-9);
  EXPECT_EQ(sub[0].estimates, (std::vector<int>{10, 11, 12}));
  EXPECT_NEAR(sub[1].objective, 1.0 + 2.0 * (1.0 - 0.06 * 0.06 / (kRadius * kRadius)), 1e-9);
  EXPECT_EQ(sub[1].estimates, (std::vector<int>{20, 21, 22}));
}

TEST(IsmRecognizer, VoteExactlyOnABinBorderMatchesAHypothesisInTheNeighbouringBin) {
  // Bin size and coordinates exactly representable in binary, identity orientations, so the
  // votes land exactly where written. R and B vote at the centre of cell (0, 0, 0); A's vote lands
  // exactly on the border of the next cell(s). Only the search over neighbouring bins can match it.
  const double bin = 0.125;
  IsmRecognitionParameters parameters;
  parameters.bin_size = bin;
  Ism ism;
  ism.name = "border";
  ism.reference = {"R", ""};
  ism.members = {{{"R", ""}, -1, {{Pose::identity(), 1}}},
                 {{"A", ""}, -1, {{makePose(-0.25, 0.0, 0.0), 1}}},
                 {{"B", ""}, -1, {{Pose::identity(), 1}}}};
  const Eigen::Vector3d centre(0.0625, 0.0625, 0.0625);
  struct Case {
    Eigen::Vector3d a_vote;
    double compliance;  // 1 - |a_vote - centre|^2 / r^2, r^2 = 3/4 bin^2
  };
  // (A vote at the corner of the next cell, half a diagonal away, no longer counts.)
  const Case cases[] = {{{0.125, 0.0625, 0.0625}, 2.0 / 3.0},  // face neighbour
                        {{0.125, 0.125, 0.0625}, 1.0 / 3.0}};  // edge neighbour
  for (const Case& c : cases) {
    ASSERT_NE(VotingSpace::cellOf(c.a_vote.x(), bin), VotingSpace::cellOf(centre.x(), bin));
    const std::vector<IsmInput> inputs = {
        {kR, Pose(centre, Eigen::Quaterniond::Identity()), 1.0, {}},
        {kA,
         Pose(c.a_vote + Eigen::Vector3d(0.25, 0.0, 0.0), Eigen::Quaterniond::Identity()),
         1.0,
         {}},
        {kB, Pose(centre, Eigen::Quaterniond::Identity()), 1.0, {}}};
    const auto results = recognizeIsm(ism, inputs, parameters);
    ASSERT_FALSE(results.empty());
    EXPECT_EQ(results[0].reference_pose.position, centre);
    ASSERT_TRUE(results[0].matches[kA].matched()) << c.a_vote.transpose();
    EXPECT_NEAR(results[0].matches[kA].position_compliance, c.compliance, 1e-12);
    EXPECT_NEAR(results[0].objective, 2.0 + c.compliance, 1e-12);
  }
}

TEST(IsmRecognizer, ResultsAreDeterministic) {
  const Ism ism = threeMemberIsm();
  auto inputs = perfectInputs(ism);
  inputs.push_back({kB, movedBy(inputs[kB].pose, Eigen::Vector3d(0.03, 0.01, 0.0)), 1.0, {}});
  inputs.push_back({kA, movedBy(inputs[kA].pose, Eigen::Vector3d(0.6, 0.0, 0.0)), 1.0, {}});
  const auto first = recognizeIsm(ism, inputs, {});
  const auto second = recognizeIsm(ism, inputs, {});
  ASSERT_EQ(first.size(), second.size());
  for (std::size_t r = 0; r < first.size(); ++r) {
    EXPECT_EQ(first[r].objective, second[r].objective);
    EXPECT_EQ(first[r].reference_pose.position, second[r].reference_pose.position);
    for (std::size_t m = 0; m < first[r].matches.size(); ++m)
      EXPECT_EQ(first[r].matches[m].input, second[r].matches[m].input);
  }
}

// A turn of up to `max_angle` about a random axis.
Eigen::Quaterniond randomTurn(PortableRandom& random, double max_angle) {
  const Eigen::Vector3d axis(random.gaussian(), random.gaussian(), random.gaussian());
  return Eigen::Quaterniond(Eigen::AngleAxisd(random.uniform(0.0, max_angle), axis.normalized()));
}

Pose jittered(PortableRandom& random, const Pose& pose, double shift, double max_angle) {
  const Eigen::Vector3d offset(random.gaussian(), random.gaussian(), random.gaussian());
  return Pose(pose.position + shift * offset,
              (pose.orientation * randomTurn(random, max_angle)).normalized());
}

// An ISM as learned from a noisy demonstration: each member's relative poses scattered a few
// centimetres and degrees around one relation, so votes crowd together as in a real model.
Ism randomDemonstratedIsm(PortableRandom& random) {
  Ism ism;
  ism.name = "random";
  ism.reference = {"m0", ""};
  const std::size_t members = 2 + random.below(4);
  const std::size_t steps = 10 + random.below(50);
  for (std::size_t m = 0; m < members; ++m) {
    IsmMember member{{"m" + std::to_string(m), ""}, -1, {}};
    const Pose relation =
        m == 0 ? Pose::identity()
               : Pose(Eigen::Vector3d(random.uniform(-0.6, 0.6), random.uniform(-0.6, 0.6),
                                      random.uniform(-0.3, 0.3)),
                      randomTurn(random, M_PI));
    for (std::size_t step = 0; step < steps; ++step)
      member.relative_poses.push_back(
          {m == 0 ? relation : jittered(random, relation, 0.01, 5 * kDegree), 1});
    ism.members.push_back(member);
  }
  return ism;
}

// Inputs around one scene: every member one to four times with noise, some weighted like a
// child ISM's results, and some given twice at exactly one pose, so that votes tie exactly.
std::vector<IsmInput> randomCrowdedInputs(PortableRandom& random, const Ism& ism) {
  const Pose scene(Eigen::Vector3d(random.uniform(-2, 2), random.uniform(-2, 2), 0.8),
                   randomTurn(random, M_PI));
  std::vector<IsmInput> inputs;
  for (int m = 0; m < static_cast<int>(ism.members.size()); ++m) {
    const std::size_t copies = 1 + random.below(4);
    for (std::size_t copy = 0; copy < copies; ++copy) {
      const double weight = random.uniform() < 0.3 ? random.uniform(0.5, 3.0) : 1.0;
      inputs.push_back(
          {m, jittered(random, memberPose(ism, m, scene), 0.02, 6 * kDegree), weight, {}});
      if (random.uniform() < 0.2)
        inputs.push_back(inputs.back());
    }
  }
  return inputs;
}

// Inputs around one scene, each member once with noise: no result matches fully, and every
// hypothesis that matches each member has the same assignment, so most are beaten by one found
// before.
std::vector<IsmInput> randomSparseInputs(PortableRandom& random, const Ism& ism) {
  const Pose scene(Eigen::Vector3d(random.uniform(-2, 2), random.uniform(-2, 2), 0.8),
                   randomTurn(random, M_PI));
  std::vector<IsmInput> inputs;
  for (int m = 0; m < static_cast<int>(ism.members.size()); ++m)
    inputs.push_back({m, jittered(random, memberPose(ism, m, scene), 0.02, 6 * kDegree), 1.0, {}});
  return inputs;
}

// The same results, with their poses moved by `motion` (identity: bit for bit, tolerance 0).
void expectSameResults(const std::vector<IsmResult>& expected, const std::vector<IsmResult>& got,
                       const std::string& where, const Pose& motion = Pose::identity(),
                       double tolerance = 0.0) {
  ASSERT_EQ(expected.size(), got.size()) << where;
  const auto near = [&](double a, double b) { return std::abs(a - b) <= tolerance; };
  for (std::size_t r = 0; r < expected.size(); ++r) {
    EXPECT_NEAR(expected[r].objective, got[r].objective, tolerance) << where << ", result " << r;
    const Pose moved = compose(motion, expected[r].reference_pose);
    EXPECT_LE((moved.position - got[r].reference_pose.position).norm(), tolerance) << where;
    EXPECT_LE((moved.orientation.coeffs() - got[r].reference_pose.orientation.coeffs()).norm(),
              tolerance)
        << where;
    EXPECT_EQ(expected[r].estimates, got[r].estimates) << where;
    ASSERT_EQ(expected[r].matches.size(), got[r].matches.size()) << where;
    for (std::size_t m = 0; m < expected[r].matches.size(); ++m) {
      const MemberMatch& a = expected[r].matches[m];
      const MemberMatch& b = got[r].matches[m];
      EXPECT_TRUE(a.input == b.input && a.relative_pose == b.relative_pose &&
                  near(a.position_compliance, b.position_compliance) &&
                  near(a.orientation_compliance, b.orientation_compliance))
          << where << ", result " << r << ", member " << m;
    }
  }
}

// The search compares a member's votes only where their distance lets them come near the best
// one, and stops scoring a hypothesis that will match the same inputs as a better result found
// before; comparing every vote near each hypothesis and scoring every hypothesis above the bar
// must give the same results bit for bit (same instances, objectives, matched votes and order),
// for every kind of selection, with crowded inputs and with one input per member.
TEST(IsmRecognizer, SkippingVotesAndHypothesesThatCannotMatterChangesNoResult) {
  IsmResultSelection root, sub_ism, every, above;
  sub_ism.best_count = 4;
  every.best_count = 4;
  every.every_result_from = 1.0;
  above.at_least = 1.5;
  std::size_t compared = 0, compared_every = 0;
  std::size_t sparse_votes = 0, sparse_votes_every = 0;  // sub-ISM selections, sparse inputs
  for (std::uint32_t seed = 1; seed <= 120; ++seed) {
    PortableRandom random(seed);
    const Ism ism = randomDemonstratedIsm(random);
    const bool sparse = seed > 60;
    const std::vector<IsmInput> inputs =
        sparse ? randomSparseInputs(random, ism) : randomCrowdedInputs(random, ism);
    for (const IsmResultSelection& selection : {root, sub_ism, every, above}) {
      IsmResultSelection reference = selection;
      reference.compare_every_vote = true;
      IsmRecognitionStats stats, reference_stats;
      const auto expected = recognizeIsm(ism, inputs, {}, reference, &reference_stats);
      const auto got = recognizeIsm(ism, inputs, {}, selection, &stats);
      expectSameResults(expected, got, "seed " + std::to_string(seed));
      EXPECT_LE(stats.candidates, reference_stats.candidates);
      EXPECT_LE(stats.neighbourhood_votes, reference_stats.neighbourhood_votes);
      // (With few votes, the seeds compared to see whether every member will match can cost
      // more than they save, so comparisons are compared in sum only.)
      compared += stats.comparisons;
      compared_every += reference_stats.comparisons;
      if (sparse && selection.best_count > 0) {
        sparse_votes += stats.neighbourhood_votes;
        sparse_votes_every += reference_stats.neighbourhood_votes;
      }
    }
  }
  // The point of it: far fewer comparisons where votes crowd, and where each member is seen
  // once, fewer hypotheses of sub-ISMs scored in full.
  EXPECT_LT(compared, compared_every / 2);
  EXPECT_LT(sparse_votes, sparse_votes_every);
  std::cout << "comparisons: " << compared << " against " << compared_every
            << " comparing every vote; sub-ISMs over one input per member: " << sparse_votes
            << " neighbourhood votes against " << sparse_votes_every << "\n";
}

// A rigid motion of up to `max_shift` metres: a random turn about a random axis, or (one case in
// four each) about the x, y or z axis alone.
Pose randomRigidMotion(PortableRandom& random, double max_shift) {
  const Eigen::Vector3d shift(random.signedUniform(0.0, max_shift),
                              random.signedUniform(0.0, max_shift),
                              random.signedUniform(0.0, max_shift));
  const std::uint32_t kind = random.below(4);
  const double angle = random.uniform(-M_PI, M_PI);
  const Eigen::Quaterniond turn =
      kind == 3 ? randomTurn(random, M_PI)
                : Eigen::Quaterniond(Eigen::AngleAxisd(angle, Eigen::Vector3d::Unit(kind)));
  return Pose(shift, turn.normalized());
}

std::vector<IsmInput> movedRigidly(std::vector<IsmInput> inputs, const Pose& motion) {
  for (IsmInput& input : inputs)
    input.pose = compose(motion, input.pose);
  return inputs;
}

// Recognises, or says that the work limit was exceeded (no results, stats as far as counted).
std::vector<IsmResult> recognizeOrGiveUp(const Ism& ism, const std::vector<IsmInput>& inputs,
                                         const IsmResultSelection& selection,
                                         IsmRecognitionStats& stats, bool& given_up) {
  given_up = false;
  try {
    return recognizeIsm(ism, inputs, {}, selection, &stats);
  } catch (const IsmWorkLimitExceeded&) {
    given_up = true;
    return {};
  }
}

// Inputs as a recorded set gives them: every member once, exactly where one of its relative
// poses puts it, so that votes of different members coincide up to rounding; weights as a
// perfect child result's, a little below an integer.
std::vector<IsmInput> randomExactInputs(PortableRandom& random, const Ism& ism) {
  const Pose scene(Eigen::Vector3d(random.uniform(-2, 2), random.uniform(-2, 2), 0.8),
                   randomTurn(random, M_PI));
  std::vector<IsmInput> inputs;
  for (int m = 0; m < static_cast<int>(ism.members.size()); ++m) {
    const std::size_t relative = random.below(ism.members[m].relative_poses.size());
    const double weight = random.uniform() < 0.5 ? 1.0 + random.below(3) - 3e-15 : 1.0;
    inputs.push_back({m, memberPose(ism, m, scene, relative), weight, {}});
  }
  return inputs;
}

// The work of a recognition does not depend on where the world frame lies: the bin grid follows
// the inputs (ism_recognizer.hpp), so the same scene moved rigidly, even hundreds of metres away
// and turned about any axis, takes exactly as many votes, bins, candidates and comparisons, and a
// comparisons cap gives up in every frame or in none. Results agree to rounding.
TEST(IsmRecognizer, RigidMotionOfTheInputsChangesNoWorkCount) {
  IsmResultSelection root, sub_ism, every, above, capped;
  sub_ism.best_count = 4;
  every.best_count = 4;
  every.every_result_from = 1.0;
  above.at_least = 1.5;
  int limited = 0, completed = 0;
  for (std::uint32_t seed = 1; seed <= 80; ++seed) {
    PortableRandom random(seed);
    const Ism ism = randomDemonstratedIsm(random);
    const std::vector<IsmInput> inputs =
        seed % 2 == 0 ? randomCrowdedInputs(random, ism) : randomExactInputs(random, ism);
    IsmRecognitionStats unlimited;
    recognizeIsm(ism, inputs, {}, sub_ism, &unlimited);
    // A cap that stops the search halfway through in the original frame.
    capped.best_count = 4;
    capped.max_comparisons = unlimited.comparisons / 2;
    for (const IsmResultSelection& selection : {root, sub_ism, every, above, capped}) {
      IsmRecognitionStats expected_stats;
      bool expected_given_up;
      const auto expected =
          recognizeOrGiveUp(ism, inputs, selection, expected_stats, expected_given_up);
      (expected_given_up ? limited : completed) += 1;
      for (double max_shift : {0.5, 5.0, 400.0}) {
        const Pose motion = randomRigidMotion(random, max_shift);
        const std::string where =
            "seed " + std::to_string(seed) + ", shift up to " + std::to_string(max_shift) + " m";
        IsmRecognitionStats stats;
        bool given_up;
        const auto got =
            recognizeOrGiveUp(ism, movedRigidly(inputs, motion), selection, stats, given_up);
        EXPECT_EQ(given_up, expected_given_up) << where;
        expectSameResults(expected, got, where, motion, 1e-9);
        EXPECT_EQ(stats.votes, expected_stats.votes) << where;
        EXPECT_EQ(stats.bins, expected_stats.bins) << where;
        EXPECT_EQ(stats.candidates, expected_stats.candidates) << where;
        EXPECT_EQ(stats.comparisons, expected_stats.comparisons) << where;
        EXPECT_EQ(stats.neighbourhood_votes, expected_stats.neighbourhood_votes) << where;
      }
    }
  }
  // Both outcomes of the cap were tried.
  EXPECT_GT(limited, 0);
  EXPECT_GT(completed, 0);
}

TEST(IsmRecognizer, InvalidParametersAndInputsAreRejected) {
  const Ism ism = threeMemberIsm();
  IsmRecognitionParameters zero_bin;
  zero_bin.bin_size = 0.0;
  EXPECT_THROW(recognizeIsm(ism, perfectInputs(ism), zero_bin), InputError);
  IsmRecognitionParameters zero_angle;
  zero_angle.max_angle_deviation = 0.0;
  EXPECT_THROW(recognizeIsm(ism, perfectInputs(ism), zero_angle), InputError);
  auto bad_member = perfectInputs(ism);
  bad_member[0].member = 3;
  EXPECT_THROW(recognizeIsm(ism, bad_member, {}), InputError);
  auto bad_weight = perfectInputs(ism);
  bad_weight[1].weight = 0.0;
  EXPECT_THROW(recognizeIsm(ism, bad_weight, {}), InputError);
  auto not_finite = perfectInputs(ism);
  not_finite[2].pose.position.x() = std::nan("");
  EXPECT_THROW(recognizeIsm(ism, not_finite, {}), InputError);
  // No input, no result.
  EXPECT_TRUE(recognizeIsm(ism, {}, {}).empty());
}

}  // namespace
}  // namespace asr_ism
