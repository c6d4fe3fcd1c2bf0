#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "asr_common/object.hpp"

namespace asr_common {

/// The object a user named, as an index into `objects`: the object whose written name
/// (ObjectKey::toString: `type:id`, or `type` for an empty id) is `name`, else the only object of
/// type `name`. So every name the tools print can be given back, and a plain type suffices when
/// it is unique. Throws InputError starting with `where` for an unknown name, or one that several
/// objects answer to, listing what could be meant.
std::size_t resolveObjectName(const std::string& name, const std::vector<ObjectKey>& objects,
                              const std::string& where);

}  // namespace asr_common
