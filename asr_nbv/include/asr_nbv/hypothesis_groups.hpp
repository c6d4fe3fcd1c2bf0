#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "asr_nbv/hypotheses.hpp"

namespace asr_nbv {

/// The counting hypotheses of a set bucketed by type and a small cube of space, for the
/// planner's bounds: a group's side and proximity terms are bounded once for all its members
/// (they lie within `radius` of its centre), and whole groups are found near a position or
/// dismissed from a view. Members are stored in group order, each with its active normals.
class HypothesisGroups {
 public:
  struct Group {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // of the members' bounding box
    double radius = 0.0;                               // no member is farther from the centre
    int type = 0;
    std::uint32_t begin = 0, end = 0;  // members [begin, end)
    bool all_sides = false;  // every member recognisable from every side (orientation term 1)
  };

  /// Groups of cubes of edge `cell`; near() finds groups within `reach` on the floor.
  HypothesisGroups(const HypothesisSet& hypotheses, double cell, double reach);

  const std::vector<Group>& groups() const { return groups_; }
  /// Per member: index into HypothesisSet::hypotheses(), position, active normals
  /// (normals()[normalsBegin(m) .. normalsBegin(m + 1)); none: recognisable from every side).
  std::size_t memberIndex(std::uint32_t member) const { return index_[member]; }
  const Eigen::Vector3d& point(std::uint32_t member) const { return points_[member]; }
  std::uint32_t normalsBegin(std::uint32_t member) const { return normals_begin_[member]; }
  const Eigen::Vector3d& normal(std::uint32_t n) const { return normals_[n]; }

  /// The groups that may have a member within the constructor's `reach` of `point` on the
  /// floor, in group order.
  std::vector<std::uint32_t> near(const Eigen::Vector2d& point) const;

 private:
  std::vector<Group> groups_;
  std::vector<std::size_t> index_;
  std::vector<Eigen::Vector3d> points_;
  std::vector<std::uint32_t> normals_begin_;
  std::vector<Eigen::Vector3d> normals_;
  // Group centres bucketed by floor cells a quarter of the reach wide.
  double reach_, grid_cell_, largest_radius_ = 0.0;
  Eigen::Vector2d low_ = Eigen::Vector2d::Zero();
  long columns_ = 0, rows_ = 0;
  std::vector<std::vector<std::uint32_t>> cells_;
  std::pair<long, long> cellOf(const Eigen::Vector2d& point) const;
};

}  // namespace asr_nbv
