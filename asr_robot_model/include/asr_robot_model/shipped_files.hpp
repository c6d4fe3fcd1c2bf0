#pragma once

#include <string>

namespace asr_robot_model {

/// A file shipped with the package (`relative` to its folder, e.g. "urdf/asr_robot.urdf"): in
/// the source folder the package was built from, or, when that is gone (an installed build on
/// another machine), in the installed share folder. If neither holds it, the source path, so
/// that the error reading it names where it was looked for.
std::string shippedFile(const std::string& relative);

}  // namespace asr_robot_model
