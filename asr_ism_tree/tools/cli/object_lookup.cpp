#include "asr_ism_tree/cli/object_lookup.hpp"

#include "asr_common/input_error.hpp"

namespace asr_ism_tree::cli {

std::size_t findObject(const std::string& name, const std::vector<asr_common::ObjectKey>& objects,
                       const std::string& what) {
  const std::size_t colon = name.find(':');
  const std::string type = name.substr(0, colon);
  std::vector<std::size_t> matches;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (objects[i].type == type &&
        (colon == std::string::npos || objects[i].id == name.substr(colon + 1))) {
      matches.push_back(i);
    }
  }
  if (matches.size() == 1)
    return matches.front();
  std::string known;
  for (const auto& object : objects)
    known += (known.empty() ? "" : ", ") + object.toString();
  throw asr_common::InputError(what + ": " +
                               (matches.empty() ? "unknown object '" : "ambiguous object '") +
                               name + "' (objects: " + known + ")");
}

}  // namespace asr_ism_tree::cli
