#include "asr_nbv/hypothesis_groups.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace asr_nbv {
namespace {

constexpr double kCellsPerReach = 4.0;
// Covers the rounding of the members' distances to the centre.
constexpr double kRadiusMargin = 1e-9;

using CellKey = std::tuple<int, long, long, long>;  // type, cube

CellKey cellKeyOf(const Hypothesis& hypothesis, double cell) {
  const Eigen::Vector3d& p = hypothesis.box.pose.position;
  return {hypothesis.type, static_cast<long>(std::floor(p.x() / cell)),
          static_cast<long>(std::floor(p.y() / cell)), static_cast<long>(std::floor(p.z() / cell))};
}

}  // namespace

HypothesisGroups::HypothesisGroups(const HypothesisSet& hypotheses, double cell, double reach)
    : reach_(reach), grid_cell_(reach / kCellsPerReach) {
  const auto& all = hypotheses.hypotheses();
  std::vector<std::pair<CellKey, std::size_t>> keyed;
  for (std::size_t i = 0; i < all.size(); ++i)
    if (all[i].counts())
      keyed.emplace_back(cellKeyOf(all[i], cell), i);
  std::sort(keyed.begin(), keyed.end());
  normals_begin_.reserve(keyed.size() + 1);
  for (std::size_t k = 0; k < keyed.size(); ++k) {
    if (k == 0 || keyed[k].first != keyed[k - 1].first) {
      Group group;
      group.type = std::get<0>(keyed[k].first);
      group.begin = static_cast<std::uint32_t>(index_.size());
      group.all_sides = true;
      groups_.push_back(group);
    }
    const Hypothesis& hypothesis = all[keyed[k].second];
    index_.push_back(keyed[k].second);
    points_.push_back(hypothesis.box.pose.position);
    normals_begin_.push_back(static_cast<std::uint32_t>(normals_.size()));
    for (std::size_t n = 0; n < hypothesis.normals.size(); ++n)
      if (hypothesis.active[n])
        normals_.push_back(hypothesis.normals[n]);
    groups_.back().end = static_cast<std::uint32_t>(index_.size());
    groups_.back().all_sides = groups_.back().all_sides && hypothesis.normals.empty();
  }
  normals_begin_.push_back(static_cast<std::uint32_t>(normals_.size()));
  if (groups_.empty())
    return;

  Eigen::Vector2d low = Eigen::Vector2d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector2d high = -low;
  for (Group& group : groups_) {
    Eigen::Vector3d box_low = points_[group.begin], box_high = box_low;
    for (std::uint32_t m = group.begin; m < group.end; ++m) {
      box_low = box_low.cwiseMin(points_[m]);
      box_high = box_high.cwiseMax(points_[m]);
    }
    group.centre = (box_low + box_high) / 2.0;
    for (std::uint32_t m = group.begin; m < group.end; ++m)
      group.radius = std::max(group.radius, (points_[m] - group.centre).norm());
    group.radius = group.radius * (1.0 + kRadiusMargin) + kRadiusMargin;
    largest_radius_ = std::max(largest_radius_, group.radius);
    low = low.cwiseMin(group.centre.head<2>());
    high = high.cwiseMax(group.centre.head<2>());
  }
  low_ = low;
  columns_ = static_cast<long>(std::floor((high.x() - low.x()) / grid_cell_)) + 1;
  rows_ = static_cast<long>(std::floor((high.y() - low.y()) / grid_cell_)) + 1;
  cells_.resize(static_cast<std::size_t>(columns_ * rows_));
  for (std::uint32_t g = 0; g < groups_.size(); ++g) {
    const auto [column, row] = cellOf(groups_[g].centre.head<2>());
    cells_[static_cast<std::size_t>(row * columns_ + column)].push_back(g);
  }
}

std::pair<long, long> HypothesisGroups::cellOf(const Eigen::Vector2d& point) const {
  return {static_cast<long>(std::floor((point.x() - low_.x()) / grid_cell_)),
          static_cast<long>(std::floor((point.y() - low_.y()) / grid_cell_))};
}

std::vector<std::uint32_t> HypothesisGroups::near(const Eigen::Vector2d& point) const {
  std::vector<std::uint32_t> found;
  if (cells_.empty())
    return found;
  // Marks instead of a sort: group order is kept without sorting.
  thread_local std::vector<char> marked;
  marked.assign(groups_.size(), 0);
  std::size_t first = groups_.size(), last = 0, hits = 0;
  const double reach = reach_ + largest_radius_;
  const auto [low_column, low_row] = cellOf(point - Eigen::Vector2d::Constant(reach));
  const auto [high_column, high_row] = cellOf(point + Eigen::Vector2d::Constant(reach));
  for (long row = std::max(0L, low_row); row <= std::min(rows_ - 1, high_row); ++row) {
    for (long column = std::max(0L, low_column); column <= std::min(columns_ - 1, high_column);
         ++column) {
      const std::vector<std::uint32_t>& cell =
          cells_[static_cast<std::size_t>(row * columns_ + column)];
      if (cell.empty())
        continue;
      const Eigen::Vector2d corner = low_ + grid_cell_ * Eigen::Vector2d(column, row);
      // The cell's farthest point from `point`: within reach of it, so is every group in it.
      const Eigen::Vector2d far_corner(
          std::max(std::abs(corner.x() - point.x()), std::abs(corner.x() + grid_cell_ - point.x())),
          std::max(std::abs(corner.y() - point.y()),
                   std::abs(corner.y() + grid_cell_ - point.y())));
      const bool inside = far_corner.norm() < reach_ * (1.0 - 1e-9);
      for (std::uint32_t g : cell) {
        if (inside || (groups_[g].centre.head<2>() - point).norm() <= reach_ + groups_[g].radius) {
          marked[g] = 1;
          first = std::min<std::size_t>(first, g);
          last = std::max<std::size_t>(last, g);
          ++hits;
        }
      }
    }
  }
  found.reserve(hits);
  for (std::size_t g = first; hits > 0 && g <= last; ++g)
    if (marked[g])
      found.push_back(static_cast<std::uint32_t>(g));
  return found;
}

}  // namespace asr_nbv
