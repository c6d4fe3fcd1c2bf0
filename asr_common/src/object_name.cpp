#include "asr_common/object_name.hpp"

#include "asr_common/input_error.hpp"

namespace asr_common {
namespace {

std::string writtenNames(const std::vector<ObjectKey>& objects,
                         const std::vector<std::size_t>& indices) {
  std::string names;
  for (std::size_t i : indices)
    names += (names.empty() ? "" : ", ") + objects[i].toString();
  return names;
}

}  // namespace

std::size_t resolveObjectName(const std::string& name, const std::vector<ObjectKey>& objects,
                              const std::string& where) {
  std::vector<std::size_t> exact, by_type, all;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (objects[i].toString() == name)
      exact.push_back(i);
    if (objects[i].type == name)
      by_type.push_back(i);
    all.push_back(i);
  }
  if (exact.size() == 1)
    return exact.front();
  if (exact.size() > 1) {
    throw InputError(where + ": object '" + name + "' is ambiguous (" +
                     writtenNames(objects, exact) + ")");
  }
  if (by_type.size() == 1)
    return by_type.front();
  if (by_type.size() > 1) {
    throw InputError(where + ": object type '" + name + "' is ambiguous; write one of " +
                     writtenNames(objects, by_type));
  }
  throw InputError(where + ": unknown object '" + name +
                   "' (the scene has: " + writtenNames(objects, all) + ")");
}

}  // namespace asr_common
