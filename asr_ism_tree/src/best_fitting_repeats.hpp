#pragma once

#include <vector>

#include "asr_common/pose.hpp"
#include "asr_ism_tree/repeated_detections.hpp"

namespace asr_ism_tree {

/// Where an instance found over the representatives of repeated detections puts one object: at
/// a leaf of the tree where it was matched, the pose from which its matched vote would fall on
/// that ISM's reference pose exactly.
struct ExpectedPose {
  int object = -1;
  asr_common::Pose pose;
};

/// The estimates a further evaluation over repeated detections starts from: per object with
/// expected poses, the `per_object` estimates of `every_estimate` nearest to them (the sum over
/// its expected poses of the squared distance and angle, each in units of `tolerance`; the first
/// of equals) and, if `nearest_to_each`, the `per_object` nearest to each of its expected poses
/// as well (where several ISMs hold an object, the best instance may match a different repeat
/// in each), its representatives elsewhere left out; objects without expected poses keep
/// their representatives. Each list keeps the order of `every_estimate`. Linear in the
/// estimates: the exhaustive best often combines repeats that fit such an instance well, and a
/// best found early lets the exact search prune the rest.
std::vector<std::vector<int>> bestFittingRepeats(
    const std::vector<ExpectedPose>& expected, const std::vector<std::vector<int>>& representatives,
    const std::vector<std::vector<int>>& every_estimate, const std::vector<asr_common::Pose>& poses,
    const RepeatedDetectionTolerance& tolerance, std::size_t per_object, bool nearest_to_each);

}  // namespace asr_ism_tree
