#include "asr_nbv/candidate_views.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "asr_robot_model/forward_kinematics.hpp"

namespace asr_nbv {

CandidateOrientations::CandidateOrientations(const asr_robot_model::RobotDescription& robot,
                                             double step, unsigned seed) {
  std::mt19937 random(seed);
  const double low = robot.tilt.lower, high = robot.tilt.upper;
  const int intervals = std::max(1, static_cast<int>(std::ceil((high - low) / step)));
  for (int i = 0; i <= intervals; ++i) {
    TiltLevel level;
    level.tilt = low + (high - low) * i / intervals;
    const Eigen::Isometry3d camera = asr_robot_model::cameraInBase(robot, 0.0, level.tilt);
    const Eigen::Vector3d axis = camera.linear() * Eigen::Vector3d::UnitZ();
    level.elevation = std::asin(std::clamp(axis.z(), -1.0, 1.0));
    level.camera_height = camera.translation().z();
    const double circle = 2.0 * M_PI * std::cos(level.elevation);
    level.headings = std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(circle / step)));
    level.heading_step = 2.0 * M_PI / level.headings;
    // mt19937's output is the same everywhere (distributions are not): a portable offset.
    level.first_heading = level.heading_step * (random() / 4294967296.0);
    level.first_orientation = rotations_.size();
    const double axis_heading = std::atan2(axis.y(), axis.x());
    for (std::size_t h = 0; h < level.headings; ++h) {
      const double heading = level.first_heading + h * level.heading_step;
      const Eigen::Matrix3d rotation =
          Eigen::AngleAxisd(heading - axis_heading, Eigen::Vector3d::UnitZ()) * camera.linear();
      rotations_.push_back(rotation);
      axes_.push_back(rotation * Eigen::Vector3d::UnitZ());
      level_of_.push_back(levels_.size());
    }
    levels_.push_back(level);
  }
}

std::vector<Eigen::Vector2d> hexagonalLattice(const Eigen::Vector2d& centre, double radius,
                                              double reach, const Eigen::Vector2d& low,
                                              const Eigen::Vector2d& high) {
  const double column = 2.0 * radius * std::cos(M_PI / 6.0), row = 1.5 * radius;
  const int rows = static_cast<int>(std::ceil(reach / row));
  const int columns = static_cast<int>(std::ceil(reach / column)) + 1;
  std::vector<Eigen::Vector2d> points{centre};
  for (int j = -rows; j <= rows; ++j) {
    const double shift = (j % 2 != 0) ? column / 2.0 : 0.0;
    for (int i = -columns; i <= columns; ++i) {
      if (i == 0 && j == 0)
        continue;
      const Eigen::Vector2d point = centre + Eigen::Vector2d(i * column + shift, j * row);
      if ((point - centre).cwiseAbs().maxCoeff() <= reach && (point.array() >= low.array()).all() &&
          (point.array() <= high.array()).all())
        points.push_back(point);
    }
  }
  return points;
}

}  // namespace asr_nbv
