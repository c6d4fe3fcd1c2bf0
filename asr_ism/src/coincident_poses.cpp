#include "asr_ism/coincident_poses.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace asr_ism {
namespace {

constexpr double kDistance = 1e-9;      // metres
constexpr double kDotBelowOne = 1e-12;  // of the orientations' dot product
constexpr double kCell = 1e-6;          // metres; far above kDistance

bool coincide(const asr_common::Pose& a, const asr_common::Pose& b) {
  return (a.position - b.position).norm() <= kDistance &&
         std::abs(a.orientation.dot(b.orientation)) >= 1.0 - kDotBelowOne;
}

using Cell = std::array<std::int64_t, 3>;

Cell cellOf(const Eigen::Vector3d& p) {
  return {static_cast<std::int64_t>(std::floor(p.x() / kCell)),
          static_cast<std::int64_t>(std::floor(p.y() / kCell)),
          static_cast<std::int64_t>(std::floor(p.z() / kCell))};
}

// The cells a pose within kDistance of `coordinate` may lie in along one axis, as offsets from
// its own (first to last): a neighbour only where the coordinate is that close to the border
// (twice, for the rounding of the division). No allocation: this runs for every hypothesis
// where a sub-ISM passes up every result reaching its bar.
struct Offsets {
  std::int64_t first = 0;
  std::int64_t last = 0;
};

Offsets offsetsAlong(double coordinate, std::int64_t cell) {
  const double within = coordinate / kCell - static_cast<double>(cell);
  const double border = 2.0 * kDistance / kCell;
  if (within < border)
    return {-1, 0};
  if (within > 1.0 - border)
    return {0, 1};
  return {0, 0};
}

}  // namespace

std::size_t CoincidentPoses::CellHash::operator()(const Cell& c) const {
  return static_cast<std::size_t>(c[0] * 73856093 ^ c[1] * 19349663 ^ c[2] * 83492791);
}

bool CoincidentPoses::contains(const asr_common::Pose& pose) const {
  const Cell own = cellOf(pose.position);
  const Offsets x = offsetsAlong(pose.position.x(), own[0]);
  const Offsets y = offsetsAlong(pose.position.y(), own[1]);
  const Offsets z = offsetsAlong(pose.position.z(), own[2]);
  for (std::int64_t dx = x.first; dx <= x.last; ++dx) {
    for (std::int64_t dy = y.first; dy <= y.last; ++dy) {
      for (std::int64_t dz = z.first; dz <= z.last; ++dz) {
        const auto found = cells_.find(Cell{own[0] + dx, own[1] + dy, own[2] + dz});
        if (found != cells_.end() &&
            std::any_of(found->second.begin(), found->second.end(),
                        [&](const asr_common::Pose& known) { return coincide(known, pose); }))
          return true;
      }
    }
  }
  return false;
}

void CoincidentPoses::insert(const asr_common::Pose& pose) {
  cells_[cellOf(pose.position)].push_back(pose);
}

bool CoincidentPoses::insertIfNew(const asr_common::Pose& pose) {
  if (contains(pose))
    return false;
  insert(pose);
  return true;
}

}  // namespace asr_ism
