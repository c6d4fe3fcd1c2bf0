#pragma once

#include <string>
#include <vector>

#include "asr_ism/demonstration.hpp"

namespace asr_ism::sqlite {

/// Names of the demonstrated scenes (table recorded_patterns) in a file of the original ASR
/// schema, in id order. Throws InputError naming the file if it is missing or not of that schema.
std::vector<std::string> listRecordedScenes(const std::string& path);

/// Reads the demonstration of `scene` from a file of the original ASR schema: one time step per
/// row of recorded_sets (ordered by id), the objects (recorded_objects, keyed by type and
/// observedId) in the order they first appear, poses from recorded_poses (ordered by id).
/// Quaternions are stored w, x, y, z. Throws InputError naming the file and the row for an
/// unknown scene, an empty demonstration, a NULL or empty type, a pose value that is NULL (a NaN),
/// text or out of range (validatedPose), or two poses of one object in one set.
Demonstration readDemonstration(const std::string& path, const std::string& scene);

}  // namespace asr_ism::sqlite
