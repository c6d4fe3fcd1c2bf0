// The rating of a view: its terms on golden geometric cases, occlusion, the update after a view,
// the choice of types against brute force, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "asr_nbv/raised_cosine_bound.hpp"
#include "asr_nbv/testing/nbv_scenes.hpp"
#include "asr_nbv/view_rating.hpp"

namespace asr_nbv {
namespace {

using asr_common::Pose;

const Eigen::Vector3d kObject(3.0, 2.0, 1.0);

// A camera at `position` whose optical axis (z) points along `direction`.
Pose cameraLooking(const Eigen::Vector3d& position, const Eigen::Vector3d& direction) {
  return Pose(position,
              Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), direction.normalized()));
}

asr_robot_model::ObjectCatalogue facingPlusX() {
  asr_robot_model::ObjectType type;
  type.size = Eigen::Vector3d::Constant(0.1);
  type.normals = {Eigen::Vector3d::UnitX()};
  return {{"Box", type}};
}

HypothesisSet oneHypothesis(
    const Eigen::Vector3d& position = kObject,
    const Eigen::Quaterniond& orientation = Eigen::Quaterniond::Identity()) {
  return HypothesisSet({{{"Box", "1"}, {Pose(position, orientation)}}}, facingPlusX());
}

double middle(const NbvParameters& p) {
  return (p.frustum.near() + p.frustum.far()) / 2.0;
}

TEST(RaisedCosine, OneAtZeroFallingToZeroAtTheThreshold) {
  EXPECT_DOUBLE_EQ(raisedCosine(0.0, 1.0), 1.0);
  EXPECT_NEAR(raisedCosine(0.5, 1.0), 0.5, 1e-12);
  EXPECT_EQ(raisedCosine(1.0, 1.0), 0.0);
  EXPECT_EQ(raisedCosine(2.0, 1.0), 0.0);
  for (double d = 0.0; d < 1.0; d += 0.01)
    EXPECT_GE(raisedCosine(d, 1.0), raisedCosine(d + 0.01, 1.0));
}

TEST(RaisedCosine, TableBoundsAreNeverBelowTheExactValueAndClose) {
  // The planner's first pass relies on these being upper bounds: random distances and angles
  // over and beyond the thresholds of the shipped parameters.
  std::mt19937 random(5);
  for (const double threshold : {0.55, 10.0 * M_PI / 180.0, M_PI / 4.0, M_PI}) {
    const RaisedCosineBound bound(threshold);
    std::uniform_real_distribution<double> distance(0.0, 1.5 * threshold), angle(0.0, M_PI);
    for (int i = 0; i < 20000; ++i) {
      const double d = distance(random), a = angle(random);
      const double exact_d = raisedCosine(d, threshold), exact_a = raisedCosine(a, threshold);
      ASSERT_GE(bound.ofDistance(d), exact_d) << d;
      ASSERT_LE(bound.ofDistance(d), exact_d + 0.01) << d;
      ASSERT_GE(bound.ofCosine(std::cos(a)), exact_a) << a;
      ASSERT_LE(bound.ofCosine(std::cos(a)), exact_a + 0.01) << a;
    }
    EXPECT_GE(bound.ofCosine(1.0), 1.0);
    EXPECT_EQ(bound.ofDistance(2.0 * threshold), 0.0);
  }
}

TEST(ViewRating, HypothesisFacingTheCameraCentredAtMiddleDistanceHasUtilityOne) {
  const NbvParameters p;
  const HypothesisSet set = oneHypothesis();
  const Pose camera =
      cameraLooking(kObject + middle(p) * Eigen::Vector3d::UnitX(), -Eigen::Vector3d::UnitX());
  EXPECT_NEAR(hypothesisUtility(camera, set.hypotheses()[0], p), 1.0, 1e-12);
  const ViewUtility view = viewUtility(camera, set, p, nullptr);
  EXPECT_NEAR(view.total, 1.0, 1e-12);
  ASSERT_EQ(view.per_type.size(), 1u);
}

TEST(ViewRating, AnyOtherViewOfItSeesLess) {
  const NbvParameters p;
  const HypothesisSet set = oneHypothesis();
  std::mt19937 random(7);
  std::normal_distribution<double> g(0.0, 0.2);
  for (int i = 0; i < 500; ++i) {
    const Eigen::Vector3d position = kObject + middle(p) * Eigen::Vector3d::UnitX() +
                                     Eigen::Vector3d(g(random), g(random), g(random));
    const Eigen::Vector3d aim = kObject + Eigen::Vector3d(g(random), g(random), g(random)) * 0.3;
    const double u =
        hypothesisUtility(cameraLooking(position, aim - position), set.hypotheses()[0], p);
    EXPECT_GE(u, 0.0);
    EXPECT_LT(u, 1.0);
  }
}

TEST(ViewRating, EachTermVanishesBeyondItsThreshold) {
  const NbvParameters p;
  const HypothesisSet set = oneHypothesis();
  const Hypothesis& h = set.hypotheses()[0];
  // From behind (-x): the only normal faces away.
  EXPECT_EQ(hypothesisUtility(cameraLooking(kObject - middle(p) * Eigen::Vector3d::UnitX(),
                                            Eigen::Vector3d::UnitX()),
                              h, p),
            0.0);
  // From 50 deg off the normal: beyond the rating angle of 45 deg.
  const Eigen::Vector3d oblique(std::cos(50.0 * M_PI / 180), std::sin(50.0 * M_PI / 180), 0.0);
  EXPECT_EQ(hypothesisUtility(cameraLooking(kObject + middle(p) * oblique, -oblique), h, p), 0.0);
  // Too close and too far.
  for (double distance : {0.3, 1.6})
    EXPECT_EQ(hypothesisUtility(cameraLooking(kObject + distance * Eigen::Vector3d::UnitX(),
                                              -Eigen::Vector3d::UnitX()),
                                h, p),
              0.0)
        << distance;
  // Looking 11 deg beside it: beyond half the smaller field of view (10 deg).
  const Eigen::Vector3d camera = kObject + middle(p) * Eigen::Vector3d::UnitX();
  const Eigen::Vector3d beside =
      Eigen::AngleAxisd(11.0 * M_PI / 180, Eigen::Vector3d::UnitZ()) * -Eigen::Vector3d::UnitX();
  EXPECT_EQ(hypothesisUtility(cameraLooking(camera, beside), h, p), 0.0);
}

TEST(ViewRating, NormalsTurnWithThePose) {
  const NbvParameters p;
  // Turned 90 deg about z, the normal faces +y.
  const HypothesisSet set = oneHypothesis(
      kObject, Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ())));
  EXPECT_NEAR(hypothesisUtility(cameraLooking(kObject + middle(p) * Eigen::Vector3d::UnitY(),
                                              -Eigen::Vector3d::UnitY()),
                                set.hypotheses()[0], p),
              1.0, 1e-12);
  EXPECT_EQ(hypothesisUtility(cameraLooking(kObject + middle(p) * Eigen::Vector3d::UnitX(),
                                            -Eigen::Vector3d::UnitX()),
                              set.hypotheses()[0], p),
            0.0);
}

TEST(ViewRating, HypothesisBehindACupboardIsNotCountedFromTheFarSide) {
  const NbvParameters p;
  asr_robot_model::World world = testing::emptyRoom(6.0, 5.0);
  // The cupboard stands between the object (facing +x) and a camera on the +x side.
  world.furniture = {
      testing::furniture("cupboard", kObject + Eigen::Vector3d(0.45, 0, 0), {0.3, 1.0, 2.0})};
  const asr_robot_model::WorldMap map(world, 0.03, 0.3);
  const HypothesisSet set = oneHypothesis();
  const Pose camera =
      cameraLooking(kObject + middle(p) * Eigen::Vector3d::UnitX(), -Eigen::Vector3d::UnitX());
  EXPECT_NEAR(viewUtility(camera, set, p, nullptr).total, 1.0, 1e-12);  // without the world
  EXPECT_EQ(viewUtility(camera, set, p, &map).total, 0.0);
  // Without the cupboard it counts again.
  const asr_robot_model::WorldMap empty(testing::emptyRoom(6.0, 5.0), 0.03, 0.3);
  EXPECT_NEAR(viewUtility(camera, set, p, &empty).total, 1.0, 1e-12);
}

TEST(ViewUpdate, AfterAViewTheSameViewSeesNothing) {
  const NbvParameters p;
  HypothesisSet set = oneHypothesis();
  const Pose camera =
      cameraLooking(kObject + middle(p) * Eigen::Vector3d::UnitX(), -Eigen::Vector3d::UnitX());
  EXPECT_EQ(updateAfterView(set, camera, {"Other"}, p, nullptr), 0u);  // not searched
  EXPECT_GT(viewUtility(camera, set, p, nullptr).total, 0.99);
  EXPECT_EQ(updateAfterView(set, camera, {"Box"}, p, nullptr), 1u);
  EXPECT_EQ(viewUtility(camera, set, p, nullptr).total, 0.0);
  EXPECT_FALSE(set.hypotheses()[0].counts());
  EXPECT_EQ(set.countingHypotheses(), 0u);
  set.reset();
  EXPECT_NEAR(viewUtility(camera, set, p, nullptr).total, 1.0, 1e-12);
}

TEST(ViewUpdate, OnlyNormalsWithinTheUpdateAngleAreDeactivated) {
  const NbvParameters p;
  asr_robot_model::ObjectCatalogue catalogue;
  catalogue["Box"].size = Eigen::Vector3d::Constant(0.1);
  catalogue["Box"].normals = {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(),
                              -Eigen::Vector3d::UnitX()};
  HypothesisSet set({{{"Box", "1"}, {Pose(kObject, Eigen::Quaterniond::Identity())}}}, catalogue);
  const Eigen::Vector3d from(std::cos(0.6), std::sin(0.6), 0.0);  // 34 deg from +x, 56 from +y
  EXPECT_EQ(
      updateAfterView(set, cameraLooking(kObject + middle(p) * from, -from), {"Box"}, p, nullptr),
      1u);
  const Hypothesis& h = set.hypotheses()[0];
  EXPECT_EQ(h.active, (std::vector<char>{0, 1, 1}));
  EXPECT_EQ(h.active_count, 2);
  // A view from outside the frustum's reach changes nothing.
  EXPECT_EQ(
      updateAfterView(
          set, cameraLooking(kObject + 3.0 * Eigen::Vector3d::UnitY(), -Eigen::Vector3d::UnitY()),
          {"Box"}, p, nullptr),
      0u);
}

TEST(ViewUpdate, RemovedObjectsStopCounting) {
  HypothesisSet set({{{"A", "1"}, {Pose(kObject, Eigen::Quaterniond::Identity())}},
                     {{"A", "2"}, {Pose(kObject, Eigen::Quaterniond::Identity())}},
                     {{"B", "1"}, {Pose(kObject, Eigen::Quaterniond::Identity())}}},
                    {});
  EXPECT_EQ(set.removeObjects({{"A", "2"}}), 1u);
  EXPECT_EQ(set.countingTypes(), 2u);
  EXPECT_EQ(set.removeObjects({{"A", ""}}), 1u);
  EXPECT_EQ(set.countingTypes(), 1u);
  set.reset();
  EXPECT_EQ(set.countingHypotheses(), 3u);
}

// The best subset by brute force over all non-empty subsets.
double bruteForceBest(const std::vector<double>& u, double u_max, std::size_t type_count,
                      const RatingWeights& w) {
  double best = -std::numeric_limits<double>::infinity();
  for (unsigned mask = 1; mask < (1u << u.size()); ++mask) {
    double sum = 0.0;
    int k = 0;
    for (std::size_t t = 0; t < u.size(); ++t) {
      if (mask & (1u << t)) {
        sum += u[t];
        ++k;
      }
    }
    best = std::max(best, w.utility * sum / u_max + w.recognition * (1.0 - double(k) / type_count));
  }
  return best;
}

TEST(TypeSubset, SortingFindsTheBruteForceOptimum) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> size(1, 9);
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<double> u(size(random));
    for (double& value : u)
      value = unit(random) < 0.3 ? 0.0 : unit(random) * 2.0;
    // Some ties.
    if (u.size() > 1 && unit(random) < 0.2)
      u[1] = u[0];
    double total = 0.0;
    for (double value : u)
      total += value;
    if (total == 0.0)
      u[0] = total = 0.5;
    RatingWeights w;
    w.utility = unit(random) * 100.0 + 0.1;
    w.recognition = unit(random) * 100.0;
    const double u_max = total * (1.0 + unit(random));
    const TypeChoice choice = bestTypeSubset(u, u_max, u.size(), w);
    ASSERT_FALSE(choice.types.empty());
    double sum = 0.0;
    for (int t : choice.types)
      sum += u[t];
    EXPECT_DOUBLE_EQ(sum, choice.utility);
    const double value =
        w.utility * sum / u_max + w.recognition * (1.0 - double(choice.types.size()) / u.size());
    EXPECT_NEAR(value, bruteForceBest(u, u_max, u.size(), w), 1e-9) << "trial " << trial;
  }
}

TEST(TypeSubset, NothingToSeeChoosesNothing) {
  EXPECT_TRUE(bestTypeSubset({0.0, 0.0}, 1.0, 2, RatingWeights{}).types.empty());
  EXPECT_TRUE(bestTypeSubset({}, 1.0, 0, RatingWeights{}).types.empty());
}

TEST(InverseCostsTest, StayingIsFreeAndEachTermIsInZeroOne) {
  const NbvParameters p;
  asr_robot_model::RobotDescription robot;
  robot.pan.lower = -1.0;
  robot.pan.upper = 1.0;
  robot.tilt.lower = -0.8;
  robot.tilt.upper = 0.4;
  const asr_robot_model::MotionSpeeds speeds;
  const asr_robot_model::RobotState here{1.0, 1.0, 0.0, 0.0, 0.0};
  const InverseCosts stay =
      inverseCosts(asr_robot_model::motionBetween(here, here, speeds), here, here, robot, 0, 3, p);
  EXPECT_DOUBLE_EQ(stay.base, 1.0);
  EXPECT_DOUBLE_EQ(stay.rotation, 1.0);
  EXPECT_DOUBLE_EQ(stay.pan_tilt, 1.0);
  EXPECT_DOUBLE_EQ(stay.recognition, 1.0);
  const asr_robot_model::RobotState there{3.0, 1.0, M_PI, 1.0, -0.8};
  const InverseCosts go = inverseCosts(asr_robot_model::motionBetween(here, there, speeds), here,
                                       there, robot, 3, 3, p);
  EXPECT_NEAR(go.base, std::exp(-4.0 / 8.0), 1e-12);  // 2 m, sigma 2 m
  EXPECT_NEAR(go.rotation, 0.5, 1e-12);               // 0 then pi on the spot
  EXPECT_NEAR(go.pan_tilt, 1.0 - 0.8 / 1.2, 1e-12);   // tilt crosses 2/3 of its range: worse
  EXPECT_DOUBLE_EQ(go.recognition, 0.0);
  EXPECT_NEAR(rating(1.0, 1.0, stay, p.weights), 1.0 - 0.0, 1e-12);
}

TEST(Hypotheses, NonFinitePosesAreRejectedAndCounted) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // Poses as a reader fills them (the Pose constructor would normalise).
  std::vector<Pose> poses(4);
  poses[0].position = poses[2].position = poses[3].position = kObject;
  poses[1].position = Eigen::Vector3d(nan, 0, 0);
  poses[2].orientation = Eigen::Quaterniond(nan, 0, 0, 0);
  poses[3].orientation = Eigen::Quaterniond(2.0, 0, 0, 0);
  const HypothesisSet set({{{"Box", "1"}, poses}}, facingPlusX());
  EXPECT_EQ(set.hypotheses().size(), 1u);
  EXPECT_EQ(set.rejectedPoses(), 3);
  ASSERT_EQ(set.warnings().size(), 1u);
  EXPECT_NE(set.warnings()[0].find("3 predicted poses rejected"), std::string::npos);
}

TEST(Hypotheses, TypeWithoutCatalogueEntryIsSeenFromEverySideWithAWarningNamingIt) {
  const NbvParameters p;
  const HypothesisSet set({{{"Mystery", "1"}, {Pose(kObject, Eigen::Quaterniond::Identity())}}},
                          facingPlusX());
  ASSERT_EQ(set.warnings().size(), 1u);
  EXPECT_NE(set.warnings()[0].find("'Mystery'"), std::string::npos);
  const Hypothesis& h = set.hypotheses()[0];
  EXPECT_TRUE(h.normals.empty());
  EXPECT_EQ(h.box.size, Eigen::Vector3d::Constant(kUnknownTypeSize));
  for (const Eigen::Vector3d& from : std::vector<Eigen::Vector3d>{
           Eigen::Vector3d::UnitX(), Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d::UnitY()})
    EXPECT_NEAR(hypothesisUtility(cameraLooking(kObject + middle(p) * from, -from), h, p), 1.0,
                1e-12);
}

TEST(Hypotheses, EmptyCloudsMakeNothingToSearch) {
  const HypothesisSet set({{{"Box", "1"}, {}}}, facingPlusX());
  EXPECT_TRUE(set.hypotheses().empty());
  EXPECT_EQ(set.countingHypotheses(), 0u);
  EXPECT_TRUE(set.warnings().empty());
}

}  // namespace
}  // namespace asr_nbv
