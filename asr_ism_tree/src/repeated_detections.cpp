#include "asr_ism_tree/repeated_detections.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>

namespace asr_ism_tree {
namespace {

using Cell = std::array<std::int64_t, 3>;

Cell cellOf(const Eigen::Vector3d& position, double size) {
  return {static_cast<std::int64_t>(std::floor(position.x() / size)),
          static_cast<std::int64_t>(std::floor(position.y() / size)),
          static_cast<std::int64_t>(std::floor(position.z() / size))};
}

// A group of repeated detections: positions in the list of estimates.
struct Group {
  std::size_t first;
  std::vector<std::size_t> members;
};

// The earliest group whose first estimate is within the tolerance of `pose`, or -1. Groups are
// found through a grid of cells as large as the distance tolerance: only the 27 cells around.
int matchingGroup(const asr_common::Pose& pose, const std::vector<const asr_common::Pose*>& poses,
                  const std::vector<Group>& groups, const std::map<Cell, std::vector<int>>& grid,
                  const RepeatedDetectionTolerance& tolerance) {
  const Cell centre = cellOf(pose.position, tolerance.distance);
  int found = -1;
  for (std::int64_t dx = -1; dx <= 1; ++dx) {
    for (std::int64_t dy = -1; dy <= 1; ++dy) {
      for (std::int64_t dz = -1; dz <= 1; ++dz) {
        const auto cell = grid.find({centre[0] + dx, centre[1] + dy, centre[2] + dz});
        if (cell == grid.end())
          continue;
        for (int group : cell->second) {
          if (found >= 0 && group > found)
            break;  // groups are listed in the order they opened
          const asr_common::Pose& first = *poses[groups[group].first];
          if ((first.position - pose.position).norm() <= tolerance.distance &&
              asr_common::angleBetween(first.orientation, pose.orientation) <= tolerance.angle)
            found = group;
        }
      }
    }
  }
  return found;
}

// The member nearest to the group's mean pose (distance and angle each in units of the
// tolerance): a detection near the consensus, not an outlier at the group's edge.
std::size_t representative(const Group& group, const std::vector<const asr_common::Pose*>& poses,
                           const RepeatedDetectionTolerance& tolerance) {
  if (group.members.size() == 1)
    return group.first;
  Eigen::Vector3d mean_position = Eigen::Vector3d::Zero();
  Eigen::Vector4d orientation_sum = Eigen::Vector4d::Zero();
  const Eigen::Quaterniond& first = poses[group.first]->orientation;
  for (std::size_t member : group.members) {
    const asr_common::Pose& pose = *poses[member];
    mean_position += pose.position;
    // q and -q are one rotation: add each on the first's side.
    const double side = pose.orientation.dot(first) < 0.0 ? -1.0 : 1.0;
    orientation_sum += side * pose.orientation.coeffs();
  }
  mean_position /= static_cast<double>(group.members.size());
  const Eigen::Quaterniond mean_orientation(Eigen::Vector4d(orientation_sum.normalized()));
  std::size_t best = group.first;
  double best_deviation = std::numeric_limits<double>::infinity();
  for (std::size_t member : group.members) {
    const double distance = (poses[member]->position - mean_position).norm() / tolerance.distance;
    const double angle =
        asr_common::angleBetween(poses[member]->orientation, mean_orientation) / tolerance.angle;
    const double deviation = distance * distance + angle * angle;
    // By more than rounding, which differs with where the world frame lies; else the earlier.
    if (deviation < best_deviation - 1e-9) {
      best_deviation = deviation;
      best = member;
    }
  }
  return best;
}

// Positions in `estimates`, where detections are densest first (the number of detections within
// `radius`, which a rigid motion of all of them does not change; the grid only finds them),
// ties in the given order: a group then opens at the consensus of its repeats, not at their edge.
std::vector<std::size_t> densestFirst(const std::vector<const asr_common::Pose*>& poses,
                                      double radius) {
  std::map<Cell, std::vector<std::size_t>> cells;
  for (std::size_t i = 0; i < poses.size(); ++i)
    cells[cellOf(poses[i]->position, radius)].push_back(i);
  std::vector<int> density(poses.size(), 0);
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const Cell centre = cellOf(poses[i]->position, radius);
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto cell = cells.find({centre[0] + dx, centre[1] + dy, centre[2] + dz});
          if (cell == cells.end())
            continue;
          for (std::size_t other : cell->second)
            density[i] += (poses[other]->position - poses[i]->position).norm() <= radius ? 1 : 0;
        }
      }
    }
  }
  std::vector<std::size_t> order(poses.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return density[a] > density[b]; });
  return order;
}

}  // namespace

std::vector<int> mergeRepeatedDetections(const std::vector<int>& estimates,
                                         const std::vector<asr_common::Pose>& poses,
                                         const RepeatedDetectionTolerance& tolerance) {
  if (estimates.size() < 2 || !(tolerance.distance > 0.0))
    return estimates;
  std::vector<const asr_common::Pose*> pose_of(estimates.size());
  for (std::size_t i = 0; i < estimates.size(); ++i)
    pose_of[i] = &poses[estimates[i]];
  std::vector<Group> groups;
  std::map<Cell, std::vector<int>> grid;  // cell -> groups whose first estimate lies in it
  for (std::size_t position : densestFirst(pose_of, 0.5 * tolerance.distance)) {
    const asr_common::Pose& pose = *pose_of[position];
    const int group = matchingGroup(pose, pose_of, groups, grid, tolerance);
    if (group >= 0) {
      groups[group].members.push_back(position);
      continue;
    }
    grid[cellOf(pose.position, tolerance.distance)].push_back(static_cast<int>(groups.size()));
    groups.push_back({position, {position}});
  }
  // In the given order, as the estimates came.
  std::vector<bool> kept(estimates.size(), false);
  for (const Group& group : groups)
    kept[representative(group, pose_of, tolerance)] = true;
  std::vector<int> representatives;
  for (std::size_t i = 0; i < estimates.size(); ++i) {
    if (kept[i])
      representatives.push_back(estimates[i]);
  }
  return representatives;
}

}  // namespace asr_ism_tree
