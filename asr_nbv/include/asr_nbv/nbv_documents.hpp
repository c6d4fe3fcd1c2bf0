#pragma once

#include <string>
#include <vector>

#include "asr_common/pose.hpp"
#include "asr_nbv/hypotheses.hpp"

namespace asr_nbv {

/// A view already taken: the camera_optical_frame pose in map and the types searched there.
struct VisitedView {
  asr_common::Pose camera;
  std::vector<std::string> types;
};

/// Reads predicted clouds from the JSON `asr ism predict --json` prints
/// ({"predictions": [{"type", "id", "poses": [{"position": {x, y, z}, "orientation":
/// {x, y, z, w}}]}]}), or a list of such documents (several scene instances). A coordinate
/// that is null (NaN in the writer) is read as NaN, so the pose is rejected and counted when
/// hypotheses are made. Throws asr_common::InputError naming the file and the field if the
/// document is malformed.
std::vector<PredictedCloud> readPredictedClouds(const std::string& path);

/// Reads visited views: [{"camera": {"position": ..., "orientation": ...}, "types": [...]}].
/// Throws asr_common::InputError naming the file and the field for a malformed view, a
/// non-finite pose or an unnormalised quaternion.
std::vector<VisitedView> readVisitedViews(const std::string& path);

}  // namespace asr_nbv
