#pragma once

#include <string>
#include <vector>

#include "asr_common/object.hpp"

namespace asr_ism_tree::cli {

/// Index of the object a user named as `type` (if that type is unique) or `type:id`. Throws
/// InputError naming `what` for an unknown or ambiguous name.
std::size_t findObject(const std::string& name, const std::vector<asr_common::ObjectKey>& objects,
                       const std::string& what);

}  // namespace asr_ism_tree::cli
