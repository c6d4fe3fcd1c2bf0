#include "asr_common/cli/command_line.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace asr_common::cli {

CommandLine::CommandLine(const std::vector<std::string>& arguments,
                         const std::set<std::string>& value_options,
                         const std::set<std::string>& flags) {
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    const std::string& argument = arguments[i];
    if (argument.rfind("--", 0) != 0) {
      throw UsageError{"unexpected argument '" + argument + "'"};
    }
    const std::string name = argument.substr(2);
    if (flags.count(name)) {
      flags_.insert(name);
    } else if (value_options.count(name)) {
      if (i + 1 >= arguments.size())
        throw UsageError{"option --" + name + " needs a value"};
      values_[name] = arguments[++i];
    } else {
      throw UsageError{"unknown option --" + name};
    }
  }
}

std::string CommandLine::required(const std::string& name) const {
  const auto found = values_.find(name);
  if (found == values_.end())
    throw UsageError{"option --" + name + " is required"};
  return found->second;
}

std::string CommandLine::optional(const std::string& name, const std::string& fallback) const {
  const auto found = values_.find(name);
  return found == values_.end() ? fallback : found->second;
}

double CommandLine::number(const std::string& name, double fallback) const {
  const auto found = values_.find(name);
  if (found == values_.end())
    return fallback;
  char* end = nullptr;
  const double value = std::strtod(found->second.c_str(), &end);
  if (found->second.empty() || *end != '\0' || !std::isfinite(value)) {
    throw UsageError{"option --" + name + " needs a number, not '" + found->second + "'"};
  }
  return value;
}

long long CommandLine::integer(const std::string& name, long long fallback) const {
  const auto found = values_.find(name);
  if (found == values_.end())
    return fallback;
  char* end = nullptr;
  errno = 0;
  const long long value = std::strtoll(found->second.c_str(), &end, 10);
  if (found->second.empty() || *end != '\0' || value < 0 || errno == ERANGE) {
    throw UsageError{"option --" + name + " needs a non-negative integer, not '" + found->second +
                     "'"};
  }
  return value;
}

}  // namespace asr_common::cli
