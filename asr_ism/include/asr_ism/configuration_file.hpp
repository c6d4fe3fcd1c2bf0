#pragma once

#include <string>

#include "asr_ism/common_types.hpp"

namespace asr_ism {

/// Reads an object configuration from a YAML or JSON file of the form
///   objects: [{type, id, pose: {position: {x, y, z}, orientation: {x, y, z, w}}}]
/// (geometry_msgs field names; `id` may be left out). Throws InputError naming the file and the
/// object for a missing file, malformed YAML/JSON, content after the objects (trailing text, a
/// second document), a key given twice, a missing field, a non-number, a non-finite
/// value, a zero or unnormalised quaternion, or an empty type.
Configuration readConfigurationFile(const std::string& path);

/// Writes a configuration in the format readConfigurationFile reads (YAML), via a temporary
/// file and a rename, so the target is never half-written. Throws InputError if `path` exists
/// and `overwrite` is false, or if the file cannot be written.
void writeConfigurationFile(const std::string& path, const Configuration& configuration,
                            bool overwrite = false);

}  // namespace asr_ism
