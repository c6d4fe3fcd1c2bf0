#include "asr_state_machine/furniture_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "asr_robot_model/forward_kinematics.hpp"

namespace asr_state_machine {

namespace {

using asr_robot_model::Frustum;
using asr_robot_model::RobotDescription;
using asr_robot_model::WorldMap;

constexpr int kHeadings = 24;
constexpr int kTilts = 16;
constexpr double kPreferredDepthShare = 0.7;
// The sweep covers a point when a view would detect a test object standing there: boxes and
// bottles (a 0.1 x 0.1 x 0.2 m box 0.14 m above the top), and flat things such as tags, whose
// centres lie a few centimetres above the top, anywhere in the point's cell of the grid (a box
// over the whole cell, 0.08 m high), since a tag is seen from few directions and a view that
// sees the cell's middle may still cut it off.
struct SweepLayer {
  double height_above_top;
  Eigen::Vector3d test_object;  // zero x and y: the cell's
};
const SweepLayer kLayers[] = {{0.14, {0.1, 0.1, 0.2}}, {0.06, {0.0, 0.0, 0.08}}};

struct SweepPoint {
  asr_robot_model::Box test_object;  // centred on the point
};

// True if every corner of the box is in the frustum and the line of sight to its centre is free.
bool seesWhole(const Pose& camera, const asr_robot_model::Box& box, const WorldMap& map,
               const Frustum& frustum) {
  for (const Eigen::Vector3d& corner : box.corners()) {
    if (!frustum.contains(camera.orientation.conjugate() * (corner - camera.position))) {
      return false;
    }
  }
  return map.lineOfSight(camera.position, box);
}

bool sees(const Pose& camera, const Eigen::Vector3d& target, const WorldMap& map,
          const Frustum& frustum) {
  const Eigen::Vector3d in_camera = camera.orientation.conjugate() * (target - camera.position);
  if (!frustum.contains(in_camera))
    return false;
  asr_robot_model::Box point;
  point.pose = Pose(target, Eigen::Quaterniond::Identity());
  point.size = Eigen::Vector3d::Constant(0.02);
  return map.lineOfSight(camera.position, point);
}

// Points on every furniture top, `spacing` apart, at the heights of small and of tall objects
// standing on it.
std::vector<SweepPoint> pointsOnTops(const asr_robot_model::World& world, double spacing) {
  std::vector<SweepPoint> points;
  for (const asr_robot_model::Furniture& furniture : world.furniture) {
    const asr_robot_model::Box& box = furniture.box;
    const int nx = std::max(1, static_cast<int>(std::ceil(box.size.x() / spacing)));
    const int ny = std::max(1, static_cast<int>(std::ceil(box.size.y() / spacing)));
    const Eigen::Vector2d cell(box.size.x() / nx, box.size.y() / ny);
    for (const SweepLayer& layer : kLayers) {
      for (int i = 0; i < nx; ++i) {
        for (int j = 0; j < ny; ++j) {
          const Eigen::Vector3d local((i + 0.5) * cell.x() - box.size.x() / 2,
                                      (j + 0.5) * cell.y() - box.size.y() / 2,
                                      box.size.z() / 2 + layer.height_above_top);
          SweepPoint point;
          point.test_object.pose =
              Pose(box.pose.position + box.pose.orientation * local, box.pose.orientation);
          point.test_object.size = layer.test_object;
          if (layer.test_object.x() == 0.0)
            point.test_object.size.head<2>() = cell;
          points.push_back(point);
        }
      }
    }
  }
  return points;
}

}  // namespace

std::optional<SearchView> viewLookingAt(const Eigen::Vector3d& target, double approach,
                                        double half_range, const RobotDescription& robot,
                                        const WorldMap& map, const Frustum& frustum) {
  // Beyond the middle of the clipping range: there the frustum is wide and tall enough for
  // whole objects near the target, not only the target itself.
  const double middle = frustum.near() + kPreferredDepthShare * (frustum.far() - frustum.near());
  std::optional<SearchView> best;
  double best_error = std::numeric_limits<double>::infinity();
  for (int t = 0; t < kTilts; ++t) {
    const double tilt = robot.tilt.lower + (robot.tilt.upper - robot.tilt.lower) * t / (kTilts - 1);
    // With pan 0, the camera in the base frame: its height and its axis fix how far from the
    // target along the axis the camera must be.
    const Eigen::Isometry3d camera_in_base = asr_robot_model::cameraInBase(robot, 0.0, tilt);
    const Eigen::Vector3d axis = camera_in_base.linear() * Eigen::Vector3d::UnitZ();
    if (std::abs(axis.z()) < 1e-6)
      continue;
    const double depth = (target.z() - camera_in_base.translation().z()) / axis.z();
    if (depth < frustum.near() || depth > frustum.far())
      continue;
    const double error = std::abs(depth - middle);
    if (error >= best_error)
      continue;
    const double axis_heading = std::atan2(axis.y(), axis.x());
    for (int h = 0; h <= kHeadings; ++h) {
      // Offsets 0, +d, -d, +2d, ...: the approach's own direction first. The camera looks along
      // `heading`, so it stands towards heading + pi from the target.
      const double offset = ((h + 1) / 2) * (h % 2 ? 1.0 : -1.0) * half_range / (kHeadings / 2);
      const double heading = approach + M_PI + offset;
      RobotState state;
      state.yaw = asr_robot_model::wrapAngle(heading - axis_heading);
      state.tilt = tilt;
      const Eigen::Vector3d camera_offset =
          Eigen::AngleAxisd(state.yaw, Eigen::Vector3d::UnitZ()) * camera_in_base.translation();
      const Eigen::Vector3d axis_in_map =
          Eigen::AngleAxisd(state.yaw, Eigen::Vector3d::UnitZ()) * axis;
      const Eigen::Vector3d camera_position = target - depth * axis_in_map;
      state.x = camera_position.x() - camera_offset.x();
      state.y = camera_position.y() - camera_offset.y();
      if (!map.baseIsFree(state.x, state.y))
        continue;
      const Pose camera = asr_robot_model::cameraPose(robot, state);
      if (!sees(camera, target, map, frustum))
        continue;
      best = SearchView{state, camera, false};
      best_error = error;
      break;
    }
  }
  return best;
}

FurnitureSweep::FurnitureSweep(const RobotDescription& robot, const asr_robot_model::World& world,
                               const WorldMap& map, const Frustum& frustum,
                               const std::vector<asr_common::ObjectEstimate>& demonstrated,
                               double spacing, VisitedViewTolerance tolerance)
    : speeds_(asr_robot_model::speedsOf(robot)), tolerance_(tolerance) {
  for (const asr_common::ObjectEstimate& estimate : demonstrated) {
    if (auto view = viewLookingAt(estimate.pose.position, 0.0, M_PI, robot, map, frustum)) {
      view->informed = true;
      informed_.push_back({*view, {estimate.key.type}});
    }
  }
  // The sweep covers (point, side) pairs greedily: a pair no earlier view covers gets its own
  // view. A view covers a pair if it sees the point from within 45 degrees of that side.
  const std::vector<SweepPoint> points = pointsOnTops(world, spacing);
  constexpr int kSides = 4;
  const auto sideOf = [](const Eigen::Vector3d& point, const Pose& camera) {
    const Eigen::Vector3d away = camera.position - point;
    const double azimuth = std::atan2(away.y(), away.x());
    return static_cast<int>(std::lround(azimuth / (2.0 * M_PI / kSides)) + kSides) % kSides;
  };
  std::vector<char> covered(points.size() * kSides, 0);
  for (std::size_t p = 0; p < points.size(); ++p) {
    for (int side = 0; side < kSides; ++side) {
      if (covered[p * kSides + side])
        continue;
      const std::optional<SearchView> view =
          viewLookingAt(points[p].test_object.pose.position, side * 2.0 * M_PI / kSides,
                        M_PI / kSides, robot, map, frustum);
      if (!view)
        continue;
      for (std::size_t q = 0; q < points.size(); ++q) {
        if (seesWhole(view->camera, points[q].test_object, map, frustum)) {
          covered[q * kSides + sideOf(points[q].test_object.pose.position, view->camera)] = 1;
        }
      }
      sweep_.push_back(*view);
    }
  }
}

bool FurnitureSweep::nearVisited(const SearchView& view, const std::vector<std::string>& types,
                                 const std::vector<VisitedView>& visited) const {
  const Eigen::Vector3d axis = view.camera.orientation * Eigen::Vector3d::UnitZ();
  for (const VisitedView& seen : visited) {
    // A view that searched only some of the types (a next-best-view's choice) leaves the others
    // to be looked for from there.
    const bool searched_every_type =
        std::all_of(types.begin(), types.end(), [&](const std::string& type) {
          return std::count(seen.types.begin(), seen.types.end(), type) > 0;
        });
    if (!searched_every_type)
      continue;
    const Eigen::Vector3d seen_axis = seen.camera.orientation * Eigen::Vector3d::UnitZ();
    const double angle = std::acos(std::clamp(axis.dot(seen_axis), -1.0, 1.0));
    if ((view.camera.position - seen.camera.position).norm() < tolerance_.distance &&
        angle < tolerance_.angle) {
      return true;
    }
  }
  return false;
}

std::optional<SearchView> FurnitureSweep::next(const RobotState& current,
                                               const std::vector<std::string>& types,
                                               const std::vector<VisitedView>& visited) {
  std::optional<SearchView> best;
  double best_seconds = std::numeric_limits<double>::infinity();
  const auto consider = [&](const SearchView& view) {
    if (nearVisited(view, types, visited))
      return;
    const double seconds = asr_robot_model::motionBetween(current, view.state, speeds_).seconds;
    if (seconds < best_seconds) {
      best = view;
      best_seconds = seconds;
    }
  };
  for (const TypedView& informed : informed_) {
    const bool searched = std::any_of(
        informed.types.begin(), informed.types.end(),
        [&](const std::string& type) { return std::count(types.begin(), types.end(), type) > 0; });
    if (searched)
      consider(informed.view);
  }
  if (best)
    return best;
  for (const SearchView& view : sweep_)
    consider(view);
  return best;
}

}  // namespace asr_state_machine
