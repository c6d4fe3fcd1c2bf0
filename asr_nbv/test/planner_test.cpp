// The planner on whole scenes: where it goes for a far and a near object, determinism across
// thread counts and seeds, and bad input.
#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "asr_common/input_error.hpp"
#include "asr_nbv/next_best_view_planner.hpp"
#include "asr_nbv/testing/nbv_scenes.hpp"
#include "asr_robot_model/forward_kinematics.hpp"

namespace asr_nbv {
namespace {

using asr_common::Pose;
using asr_robot_model::RobotState;

const asr_robot_model::RobotDescription& robot() {
  static const asr_robot_model::RobotDescription description =
      asr_robot_model::loadRobotDescription(asr_robot_model::defaultRobotUrdf());
  return description;
}

// An object facing the camera of view `orientation` from `camera`, at middle distance on its
// optical axis.
HypothesisSet objectInView(const Eigen::Vector3d& camera, const Eigen::Matrix3d& orientation,
                           const NbvParameters& p) {
  const Eigen::Vector3d axis = orientation * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d position = camera + (p.frustum.near() + p.frustum.far()) / 2.0 * axis;
  asr_robot_model::ObjectCatalogue catalogue;
  catalogue["Box"].size = Eigen::Vector3d::Constant(0.1);
  catalogue["Box"].normals = {Eigen::Vector3d::UnitX()};
  // The object's x axis (its normal) points back at the camera.
  const Eigen::Quaterniond facing =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitX(), -axis);
  return HypothesisSet({{{"Box", "1"}, {Pose(position, facing)}}}, catalogue);
}

struct Scene {
  asr_robot_model::World world;
  asr_robot_model::WorldMap map;
  explicit Scene(asr_robot_model::World w)
      : world(std::move(w)), map(world, 0.03, robot().base_radius) {}
};

// The shipped robot with its camera on the tilt axis, so that panning does not move it: a view
// from the same place in another direction is then exactly a turn of the head.
asr_robot_model::RobotDescription cameraOnTheTiltAxis() {
  asr_robot_model::RobotDescription description = robot();
  description.tilt_to_camera.translation().setZero();
  return description;
}

TEST(Planner, NearObjectOnlyTurnsTheHead) {
  const NbvParameters p;
  const Scene scene(testing::emptyRoom(8.0, 6.0));
  const asr_robot_model::RobotDescription head = cameraOnTheTiltAxis();
  NextBestViewPlanner planner(head, scene.world, scene.map, p, nullptr, 5);
  const CandidateOrientations orientations(head, p.orientation_step, 5);
  // The robot stands with its head at one tilt level; the object is in a view of that level
  // 40 deg to the left: panning reaches it without moving the base.
  const TiltLevel& level = orientations.levels()[orientations.levels().size() / 2];
  const RobotState current{4.0, 3.0, 0.0, 0.0, level.tilt};
  const Eigen::Vector3d camera = asr_robot_model::cameraPose(head, current).position;
  std::size_t chosen = level.first_orientation;
  for (std::size_t h = 0; h < level.headings; ++h) {
    const std::size_t o = level.first_orientation + h;
    const Eigen::Vector3d axis = orientations.axis(o);
    if (std::abs(std::atan2(axis.y(), axis.x()) - 0.7) <
        std::abs(std::atan2(orientations.axis(chosen).y(), orientations.axis(chosen).x()) - 0.7))
      chosen = o;
  }
  const HypothesisSet set = objectInView(camera, orientations.rotation(chosen), p);
  const PlannedView view = planner.plan(set, current);
  ASSERT_TRUE(view.found);
  EXPECT_NEAR(view.state.x, current.x, 1e-6);
  EXPECT_NEAR(view.state.y, current.y, 1e-6);
  EXPECT_NEAR(view.state.yaw, current.yaw, 1e-4);  // the IK's pan search resolution
  EXPECT_GT(std::abs(view.state.pan), 0.5);
  EXPECT_NEAR(view.utility, 1.0, 1e-6);
  EXPECT_DOUBLE_EQ(view.costs.base, 1.0);
  EXPECT_EQ(view.types, std::vector<std::string>{"Box"});
}

TEST(Planner, LoneFarObjectMakesItDrive) {
  const NbvParameters p;
  const Scene scene(testing::emptyRoom(8.0, 6.0));
  NextBestViewPlanner planner(robot(), scene.world, scene.map, p, nullptr, 1);
  const RobotState current{1.0, 1.0, 0.0, 0.0, 0.0};
  asr_robot_model::ObjectCatalogue catalogue;
  catalogue["Box"].size = Eigen::Vector3d::Constant(0.1);
  catalogue["Box"].normals = {-Eigen::Vector3d::UnitX()};
  const Eigen::Vector3d object(6.5, 4.5, 1.0);
  const HypothesisSet set({{{"Box", "1"}, {Pose(object, Eigen::Quaterniond::Identity())}}},
                          catalogue);
  const PlannedView view = planner.plan(set, current);
  ASSERT_TRUE(view.found);
  EXPECT_GT(std::hypot(view.state.x - current.x, view.state.y - current.y), 3.0);
  EXPECT_LT(view.costs.base, 1.0);
  EXPECT_GT(hypothesisUtility(view.camera, set.hypotheses()[0], p), 0.0);
  EXPECT_NEAR(viewUtility(view.camera, set, p, &scene.map).total, view.utility, 1e-4);
  // The camera pose is what the robot state gives (forward kinematics).
  EXPECT_TRUE(asr_common::approximatelyEqual(
      view.camera, asr_robot_model::cameraPose(robot(), view.state), 1e-9, 1e-9));
  // The robot's base stands in the room.
  EXPECT_TRUE(scene.map.baseIsFree(view.state.x, view.state.y));
  EXPECT_GT(view.steps, 1u);
  EXPECT_GT(view.candidates_rated, 1000u);
}

TEST(Planner, SameAnswerForAnyThreadCount) {
  const NbvParameters p;
  const Scene scene(testing::furnishedRoom());
  const HypothesisSet set(testing::cloudsOnFurniture(scene.world, 6, 60, 11),
                          testing::twoSidedCatalogue(6));
  const RobotState current{3.0, 2.5, 0.3, 0.0, 0.0};
  std::vector<PlannedView> views;
  for (unsigned threads : {1u, 2u, 3u}) {
    asr_ism::ThreadPool pool(threads);
    views.push_back(
        NextBestViewPlanner(robot(), scene.world, scene.map, p, &pool, 9).plan(set, current));
  }
  views.push_back(
      NextBestViewPlanner(robot(), scene.world, scene.map, p, nullptr, 9).plan(set, current));
  ASSERT_TRUE(views[0].found);
  // The utility the planner rated is the one the view has (occlusion included), over its types.
  const ViewUtility seen = viewUtility(views[0].camera, set, p, &scene.map);
  double searched = 0.0;
  for (const std::string& type : views[0].types)
    searched += seen.per_type[set.typeIndex(type)];
  EXPECT_NEAR(searched, views[0].utility, 1e-4 * views[0].utility);  // IK: within 1e-6 m
  for (const PlannedView& view : views) {
    EXPECT_EQ(view.camera.position, views[0].camera.position);
    EXPECT_EQ(view.camera.orientation.coeffs(), views[0].camera.orientation.coeffs());
    EXPECT_EQ(view.types, views[0].types);
    EXPECT_EQ(view.rating, views[0].rating);
    EXPECT_EQ(view.candidates_rated, views[0].candidates_rated);
  }
}

// The branch and bound over positions and candidates chooses exactly the view that rating every
// position and orientation in full chooses, step by step: over random scenes (types, clouds,
// some normals already seen, the robot anywhere free), to the last digit.
TEST(Planner, BranchAndBoundChoosesTheExhaustiveSearchsView) {
  NbvParameters p;
  p.max_steps = 4;
  const Scene scene(testing::furnishedRoom());
  std::mt19937 random(2024);
  asr_ism::ThreadPool pool(2);
  int found = 0;
  for (unsigned trial = 0; trial < 30; ++trial) {
    // Coarser orientations on most trials: the exhaustive search rates every candidate.
    p.orientation_step = (trial % 4 == 0 ? 8.0 : 15.0) * M_PI / 180.0;
    const std::size_t types = 2 + random() % 6, poses = 2 + random() % 14;
    HypothesisSet set(testing::cloudsOnFurniture(scene.world, types, poses, trial),
                      testing::twoSidedCatalogue(types));
    std::uniform_real_distribution<double> x(0.5, 5.5), y(0.5, 4.5), angle(-M_PI, M_PI);
    RobotState current{x(random), y(random), angle(random), 0.0, 0.0};
    while (!scene.map.baseIsFree(current.x, current.y)) {
      current.x = x(random);
      current.y = y(random);
    }
    if (trial % 3 == 1)  // some sides already seen, from where the robot stands
      updateAfterView(set, asr_robot_model::cameraPose(robot(), current), set.types(), p,
                      &scene.map);
    const unsigned seed = trial;
    const PlannedView exhaustive = NextBestViewPlanner(robot(), scene.world, scene.map, p, nullptr,
                                                       seed, CandidateSearch::exhaustive)
                                       .plan(set, current);
    for (asr_ism::ThreadPool* threads : {static_cast<asr_ism::ThreadPool*>(nullptr), &pool}) {
      const PlannedView bounded =
          NextBestViewPlanner(robot(), scene.world, scene.map, p, threads, seed).plan(set, current);
      ASSERT_EQ(bounded.found, exhaustive.found) << "trial " << trial;
      EXPECT_EQ(bounded.steps, exhaustive.steps) << "trial " << trial;
      EXPECT_EQ(bounded.candidates_rated, exhaustive.candidates_rated);
      if (!exhaustive.found)
        continue;
      EXPECT_EQ(bounded.camera.position, exhaustive.camera.position) << "trial " << trial;
      EXPECT_EQ(bounded.camera.orientation.coeffs(), exhaustive.camera.orientation.coeffs());
      const RobotState& a = bounded.state;
      const RobotState& b = exhaustive.state;
      EXPECT_EQ(std::vector<double>({a.x, a.y, a.yaw, a.pan, a.tilt}),
                std::vector<double>({b.x, b.y, b.yaw, b.pan, b.tilt}))
          << "trial " << trial;
      EXPECT_EQ(bounded.types, exhaustive.types) << "trial " << trial;
      EXPECT_EQ(bounded.utility, exhaustive.utility) << "trial " << trial;
      EXPECT_EQ(bounded.utility_max, exhaustive.utility_max) << "trial " << trial;
      EXPECT_EQ(bounded.rating, exhaustive.rating) << "trial " << trial;
      // The bounded search rates in full only a part of what the exhaustive one does.
      EXPECT_LE(bounded.rated.size(), exhaustive.rated.size());
    }
    found += exhaustive.found;
  }
  EXPECT_GE(found, 20);
}

// As above on clouds like the benchmark's: hundreds of poses per object, clustered on the
// furniture, where each position's bound sums many hypotheses a single view cannot all see.
TEST(Planner, BranchAndBoundChoosesTheExhaustiveSearchsViewOnLargeClusteredClouds) {
  NbvParameters p;
  p.max_steps = 2;
  p.orientation_step = 15.0 * M_PI / 180.0;
  const Scene scene(testing::furnishedRoom());
  asr_ism::ThreadPool pool(2);
  const std::vector<RobotState> starts{
      {3.0, 2.4, 0.0, 0.0, 0.0}, {1.0, 3.5, -1.2, 0.0, 0.0}, {4.8, 1.2, 2.5, 0.0, 0.0}};
  for (unsigned trial = 0; trial < starts.size(); ++trial) {
    const std::size_t types = 4 + trial;
    const HypothesisSet set(testing::cloudsOnFurniture(scene.world, types, 150, 40 + trial),
                            testing::twoSidedCatalogue(types));
    const PlannedView exhaustive = NextBestViewPlanner(robot(), scene.world, scene.map, p, nullptr,
                                                       trial, CandidateSearch::exhaustive)
                                       .plan(set, starts[trial]);
    const PlannedView bounded =
        NextBestViewPlanner(robot(), scene.world, scene.map, p, &pool, trial)
            .plan(set, starts[trial]);
    ASSERT_TRUE(exhaustive.found) << "trial " << trial;
    ASSERT_TRUE(bounded.found) << "trial " << trial;
    EXPECT_EQ(bounded.steps, exhaustive.steps) << "trial " << trial;
    EXPECT_EQ(bounded.camera.position, exhaustive.camera.position) << "trial " << trial;
    EXPECT_EQ(bounded.camera.orientation.coeffs(), exhaustive.camera.orientation.coeffs());
    EXPECT_EQ(bounded.types, exhaustive.types) << "trial " << trial;
    EXPECT_EQ(bounded.utility, exhaustive.utility) << "trial " << trial;
    EXPECT_EQ(bounded.utility_max, exhaustive.utility_max) << "trial " << trial;
    EXPECT_EQ(bounded.rating, exhaustive.rating) << "trial " << trial;
    EXPECT_LT(bounded.rated.size(), exhaustive.rated.size());
  }
}

// As above where a panel stands across each cloud, so every view sees only part of it: the exact
// utilities fall well below the bounds without occlusion, and the normaliser's search gives up
// on many of them part way (it must never give up on the largest).
TEST(Planner, BranchAndBoundChoosesTheExhaustiveSearchsViewBehindPanels) {
  NbvParameters p;
  p.max_steps = 2;
  p.orientation_step = 15.0 * M_PI / 180.0;
  asr_ism::ThreadPool pool(2);
  for (unsigned trial = 0; trial < 3; ++trial) {
    asr_robot_model::World world = testing::furnishedRoom();
    const std::size_t types = 3 + trial;
    const std::vector<PredictedCloud> clouds =
        testing::cloudsOnFurniture(world, types, 60, 70 + trial);
    for (std::size_t t = 0; t < types; ++t) {
      const Eigen::Vector3d centre = clouds[t].poses.front().position;
      const double angle = 0.7 * static_cast<double>(t + trial);
      world.furniture.push_back({"panel_" + std::to_string(t),
                                 {asr_common::Pose(centre + Eigen::Vector3d(0.0, 0.0, 0.25),
                                                   Eigen::Quaterniond(Eigen::AngleAxisd(
                                                       angle, Eigen::Vector3d::UnitZ()))),
                                  Eigen::Vector3d(0.03, 0.8, 0.5)}});
    }
    const Scene scene(world);
    const HypothesisSet set(clouds, testing::twoSidedCatalogue(types));
    const RobotState current{3.0, 2.4, 0.5 * trial, 0.0, 0.0};
    const PlannedView exhaustive = NextBestViewPlanner(robot(), scene.world, scene.map, p, nullptr,
                                                       trial, CandidateSearch::exhaustive)
                                       .plan(set, current);
    ASSERT_TRUE(exhaustive.found) << "trial " << trial;
    for (asr_ism::ThreadPool* threads : {static_cast<asr_ism::ThreadPool*>(nullptr), &pool}) {
      const PlannedView bounded =
          NextBestViewPlanner(robot(), scene.world, scene.map, p, threads, trial)
              .plan(set, current);
      ASSERT_TRUE(bounded.found) << "trial " << trial;
      EXPECT_EQ(bounded.steps, exhaustive.steps) << "trial " << trial;
      EXPECT_EQ(bounded.camera.position, exhaustive.camera.position) << "trial " << trial;
      EXPECT_EQ(bounded.types, exhaustive.types) << "trial " << trial;
      EXPECT_EQ(bounded.utility_max, exhaustive.utility_max) << "trial " << trial;
      EXPECT_EQ(bounded.rating, exhaustive.rating) << "trial " << trial;
    }
  }
}

TEST(Planner, UpdatingAfterTheChosenViewsEventuallyLeavesNothing) {
  const NbvParameters p;
  const Scene scene(testing::furnishedRoom());
  HypothesisSet set(testing::cloudsOnFurniture(scene.world, 3, 20, 4),
                    testing::twoSidedCatalogue(3));
  asr_ism::ThreadPool pool(2);
  const NextBestViewPlanner planner(robot(), scene.world, scene.map, p, &pool, 2);
  RobotState current{3.0, 2.5, 0.0, 0.0, 0.0};
  std::size_t counting = set.countingHypotheses();
  int views = 0;
  for (; views < 60; ++views) {
    const PlannedView view = planner.plan(set, current);
    if (!view.found)
      break;
    EXPECT_GT(view.utility, 0.0);
    EXPECT_GT(updateAfterView(set, view.camera, view.types, p, &scene.map), 0u)
        << "view " << views << " deactivated nothing: the planner would repeat it forever";
    current = view.state;
    EXPECT_LE(set.countingHypotheses(), counting);
    counting = set.countingHypotheses();
  }
  EXPECT_LT(views, 60);
}

TEST(Planner, NothingToSearchIsNotFoundWithoutError) {
  const Scene scene(testing::emptyRoom(4.0, 4.0));
  const NextBestViewPlanner planner(robot(), scene.world, scene.map, NbvParameters{}, nullptr);
  const PlannedView view = planner.plan(HypothesisSet(), RobotState{1, 1, 0, 0, 0});
  EXPECT_FALSE(view.found);
}

TEST(Planner, NonFiniteCurrentStateIsRefused) {
  const Scene scene(testing::emptyRoom(4.0, 4.0));
  const NextBestViewPlanner planner(robot(), scene.world, scene.map, NbvParameters{}, nullptr);
  RobotState state{1, 1, 0, 0, 0};
  state.yaw = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(planner.plan(HypothesisSet(), state), asr_common::InputError);
}

TEST(Parameters, ShippedFileHasTheOriginalsWeights) {
  const NbvParameters p = loadNbvParameters(defaultNbvParameters());
  EXPECT_EQ(p.weights.utility, 60.0);
  EXPECT_EQ(p.weights.base, 135.0);
  EXPECT_EQ(p.weights.rotation, 10.0);
  EXPECT_EQ(p.weights.pan_tilt, 1.0);
  EXPECT_EQ(p.weights.recognition, 10.0);
  EXPECT_NEAR(p.frustum.fovx(), 30.0 * M_PI / 180.0, 1e-12);
  EXPECT_EQ(p.frustum.far(), 1.5);
}

}  // namespace
}  // namespace asr_nbv
