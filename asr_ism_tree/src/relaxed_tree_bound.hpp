#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "asr_ism_tree/ism_tree.hpp"

namespace asr_ism_tree {

/// How coarsely the relaxed evaluation groups poses, and what it may spend.
struct RelaxedBoundParameters {
  /// Votes (and sub-ISM results) within this distance and angle of a group's first one form one
  /// group, evaluated once with that much slack.
  double position_radius = 0.0;
  double angle_radius = 0.0;
  /// Cloud-to-cloud comparisons (and votes cast) allowed in one bound; beyond, no bound.
  std::size_t max_work = 0;
};

/// An upper bound of the objective any root hypothesis of the exhaustive search (every sub-ISM
/// passing every result up) reaches over these estimates, so of its best instance; nullopt where
/// computing it would take more than `max_work`.
///
/// Each ISM is evaluated over *clouds* instead of votes: votes of one member lying within the
/// radii of one another are one cloud, with how far each of them may be from its centre (in
/// position, angle, where its input is and where the hypothesis puts the member). A cloud taken
/// as the reference hypothesis scores, per member, the best similarity any of its votes could
/// have to any vote of the member's clouds, each distance shortened by both slacks (compliance
/// only falls with distance and angle, so nothing real scores more). Every candidate cloud is a
/// result passed up with that score as its weight and its slack, and the parent groups those
/// results again. Cheap where sub-ISMs pass up hundreds of near-duplicate results (votes
/// millimetres apart): they fall into a few clouds. `work`, if given, receives the work spent.
std::optional<double> relaxedRootBound(const IsmTree& tree, const std::vector<int>& bottom_up,
                                       const std::vector<asr_common::Pose>& poses,
                                       const std::vector<std::vector<int>>& estimates_of_object,
                                       const RelaxedBoundParameters& parameters,
                                       std::size_t* work = nullptr);

}  // namespace asr_ism_tree
