#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

namespace asr_common::cli {

/// Thrown for a command line that cannot be run; the tool prints usage and exits with 2.
struct UsageError {
  std::string message;
};

/// `--name value` options and `--flag` switches of one subcommand. Every option a command reads
/// must be declared, so a misspelt option is an error, not silently ignored.
class CommandLine {
 public:
  /// `value_options` take a value, `flags` do not.
  CommandLine(const std::vector<std::string>& arguments, const std::set<std::string>& value_options,
              const std::set<std::string>& flags);

  bool has(const std::string& name) const { return values_.count(name) > 0; }
  bool flag(const std::string& name) const { return flags_.count(name) > 0; }
  /// Throws UsageError naming the option if it is missing.
  std::string required(const std::string& name) const;
  std::string optional(const std::string& name, const std::string& fallback) const;
  /// Throws UsageError naming the option if its value is not a finite number.
  double number(const std::string& name, double fallback) const;
  /// The option's integer value, `fallback` if it is not given. Throws UsageError naming the
  /// option and the range if the value is not an integer in [min, max]: out of range is refused,
  /// never truncated or wrapped (the one checked integer parsing of the suite's tools).
  long long integer(const std::string& name, long long fallback, long long min,
                    long long max) const;
  /// The required option's value as exactly `count` finite numbers separated by blanks
  /// (`form` names them in the message, e.g. "x y yaw pan tilt"). Throws UsageError naming the
  /// option otherwise.
  std::vector<double> numbers(const std::string& name, std::size_t count,
                              const std::string& form) const;

 private:
  std::map<std::string, std::string> values_;
  std::set<std::string> flags_;
};

}  // namespace asr_common::cli
