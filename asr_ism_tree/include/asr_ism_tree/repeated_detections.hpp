#pragma once

#include <vector>

#include "asr_common/pose.hpp"

namespace asr_ism_tree {

/// How close two estimates of one object must be to count as one detection seen again.
struct RepeatedDetectionTolerance {
  double distance = 0.0;  // metres between the positions
  double angle = 0.0;     // radians between the orientations
};

/// Merges repeated detections of one object: `estimates` (indices into `poses`, in a canonical
/// order) are taken where they are densest first (the number of estimates within half the
/// distance tolerance; ties in the given order), each joining the first group whose first
/// estimate lies within `tolerance` of it, or opening a group; each group is represented by the
/// estimate nearest to its mean pose (distance and angle in units of the tolerance; the first of
/// those within 1e-9 of each other). Returns the representatives in the given order. Estimates
/// farther apart than the tolerance are all kept, in the given order. Nothing depends on where
/// the world frame lies but through rounding at the thresholds. Linear in the number of
/// estimates where few lie within half the tolerance of one another, quadratic in those that do
/// (the density is counted exactly).
std::vector<int> mergeRepeatedDetections(const std::vector<int>& estimates,
                                         const std::vector<asr_common::Pose>& poses,
                                         const RepeatedDetectionTolerance& tolerance);

}  // namespace asr_ism_tree
