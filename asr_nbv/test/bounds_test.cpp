// The bounds the bounded search prunes by (NextBestViewPlanner::boundsAt): over random
// hypotheses around random camera positions, neither the first pass's utility of an orientation
// nor the position's bound ever falls below the utility (occlusion aside) of the view it bounds,
// and the planner's utility before lines of sight (groups out of view skipped) is exact.
#include <gtest/gtest.h>

#include <random>

#include "asr_nbv/next_best_view_planner.hpp"
#include "asr_nbv/testing/nbv_scenes.hpp"

namespace asr_nbv {
namespace {

using asr_common::Pose;

const asr_robot_model::RobotDescription& robot() {
  static const asr_robot_model::RobotDescription description =
      asr_robot_model::loadRobotDescription(asr_robot_model::defaultRobotUrdf());
  return description;
}

// Types T0..T3: two with normals in random directions (one to three each), one with the
// catalogue's +-x, one recognisable from every side.
asr_robot_model::ObjectCatalogue randomCatalogue(std::mt19937& random) {
  std::normal_distribution<double> component(0.0, 1.0);
  asr_robot_model::ObjectCatalogue catalogue = testing::twoSidedCatalogue(4);
  for (const char* name : {"T1", "T3"}) {
    catalogue[name].normals.clear();
    const int normals = 1 + static_cast<int>(random() % 3);
    for (int n = 0; n < normals; ++n)
      catalogue[name].normals.push_back(
          Eigen::Vector3d(component(random), component(random), component(random)).normalized());
  }
  catalogue["T2"].normals.clear();
  return catalogue;
}

// Over 40 random scenes around random positions: the bounds never fall below the utility
// (occlusion aside) of a view they bound, and the planner's sum before lines of sight equals it.
// `clustered`: each cloud in a few dense clumps (several hypotheses per group of the planner,
// groups seen only in part), else scattered.
void checkBoundsOnRandomScenes(bool clustered) {
  const NbvParameters p;
  const asr_robot_model::World world = testing::emptyRoom(6.0, 5.0);
  const asr_robot_model::WorldMap map(world, p.occlusion_resolution, robot().base_radius);
  std::mt19937 random(clustered ? 78 : 77);
  std::uniform_real_distribution<double> unit(0.0, 1.0), angle(-M_PI, M_PI);
  std::size_t compared = 0, seen = 0;
  for (unsigned trial = 0; trial < 40; ++trial) {
    const NextBestViewPlanner planner(robot(), world, map, p, nullptr, trial);
    const Eigen::Vector2d position(1.5 + 3.0 * unit(random), 1.5 + 2.0 * unit(random));
    // Hypotheses within and beyond the far plane, at every height the camera may look at.
    auto random_point = [&] {
      const double along = 0.3 + 1.4 * unit(random), heading = angle(random);
      return Eigen::Vector3d(position.x() + along * std::cos(heading),
                             position.y() + along * std::sin(heading), 1.6 * unit(random));
    };
    std::vector<PredictedCloud> clouds;
    for (int t = 0; t < 4; ++t) {
      PredictedCloud cloud;
      cloud.key = {"T" + std::to_string(t), "0"};
      Eigen::Vector3d centre = random_point();
      for (int k = 0; k < 30; ++k) {
        if (clustered && k % 10 == 0)
          centre = random_point();
        Eigen::Vector3d point = random_point();
        if (clustered) {  // within 4 cm of the centre on each axis, drawn in a fixed order
          for (int axis = 0; axis < 3; ++axis)
            point[axis] = centre[axis] + 0.08 * (unit(random) - 0.5);
        }
        const Eigen::Quaterniond turn(Eigen::AngleAxisd(
            angle(random), Eigen::Vector3d(unit(random), unit(random), 1.0).normalized()));
        cloud.poses.emplace_back(point, turn);
      }
      clouds.push_back(cloud);
    }
    HypothesisSet set(clouds, randomCatalogue(random));
    // Some normals already seen.
    for (Hypothesis& hypothesis : set.hypotheses()) {
      for (std::size_t n = 0; n + 1 < hypothesis.active.size(); ++n)
        if (unit(random) < 0.3 && hypothesis.active[n]) {
          hypothesis.active[n] = 0;
          --hypothesis.active_count;
        }
    }
    const PositionBounds bounds = planner.boundsAt(set, position);
    const CandidateOrientations& orientations = planner.orientations();
    ASSERT_EQ(bounds.orientation.size(), orientations.size());
    ASSERT_EQ(bounds.unoccluded.size(), orientations.size());
    ASSERT_EQ(bounds.level.size(), orientations.levels().size());
    for (std::size_t o = 0; o < orientations.size(); ++o) {
      const TiltLevel& level = orientations.levels()[orientations.levelOf(o)];
      const Pose camera(Eigen::Vector3d(position.x(), position.y(), level.camera_height),
                        Eigen::Quaterniond(orientations.rotation(o)));
      const ViewUtility exact = viewUtility(camera, set, p, nullptr);
      for (std::size_t t = 0; t < set.types().size(); ++t) {
        EXPECT_EQ(bounds.unoccluded[o][t], exact.per_type[t])
            << "trial " << trial << " orientation " << o << " type " << t;
        EXPECT_GE(bounds.orientation[o][t], exact.per_type[t])
            << "trial " << trial << " orientation " << o << " type " << t;
        EXPECT_GE(bounds.level[orientations.levelOf(o)][t], bounds.orientation[o][t])
            << "trial " << trial << " orientation " << o << " type " << t;
        EXPECT_GE(bounds.position[t], bounds.level[orientations.levelOf(o)][t])
            << "trial " << trial << " orientation " << o << " type " << t;
        ++compared;
        seen += exact.per_type[t] > 0.0;
      }
    }
  }
  // The cases are not vacuous: many views see something.
  EXPECT_GT(seen, compared / 50);
}

TEST(PlannerBounds, NeverBelowTheUtilityOfAnyViewTheyBound) {
  checkBoundsOnRandomScenes(false);
}

TEST(PlannerBounds, NeverBelowTheUtilityOfAnyViewTheyBoundInDenseClumps) {
  checkBoundsOnRandomScenes(true);
}

}  // namespace
}  // namespace asr_nbv
