#include "asr_common/cli/command_line.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

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

long long CommandLine::integer(const std::string& name, long long fallback, long long min,
                               long long max) const {
  const auto found = values_.find(name);
  if (found == values_.end())
    return fallback;
  const std::string& text = found->second;
  const std::string range = "[" + std::to_string(min) + ", " + std::to_string(max) + "]";
  char* end = nullptr;
  errno = 0;
  const long long value = std::strtoll(text.c_str(), &end, 10);
  // strtoll would skip leading blanks and accept a sign before them; a plain integer only.
  const bool digits_first = !text.empty() && (std::isdigit(static_cast<unsigned char>(text[0])) ||
                                              (text[0] == '-' && text.size() > 1));
  if (!digits_first || *end != '\0')
    throw UsageError{"option --" + name + " needs an integer in " + range + ", not '" + text + "'"};
  if (errno == ERANGE || value < min || value > max)
    throw UsageError{"option --" + name + " is out of range: " + text + " is not in " + range};
  return value;
}

std::vector<double> CommandLine::numbers(const std::string& name, std::size_t count,
                                         const std::string& form) const {
  std::istringstream text(required(name));
  std::vector<double> values;
  std::string word;
  while (text >> word) {
    std::size_t used = 0;
    double value = NAN;
    try {
      value = std::stod(word, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != word.size() || !std::isfinite(value))
      throw UsageError{"--" + name + ": '" + word + "' is not a finite number"};
    values.push_back(value);
  }
  if (values.size() != count)
    throw UsageError{"--" + name + " takes \"" + form + "\" (" + std::to_string(count) +
                     " numbers)"};
  return values;
}

}  // namespace asr_common::cli
