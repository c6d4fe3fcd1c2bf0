#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace asr_common::cli {

/// One target a benchmark checks and how the measurement compares with it.
struct Target {
  std::string target;    // what is asked, e.g. "gedeck, complete tree: <= 1 ms"
  std::string measured;  // what was measured, e.g. "0.84 ms"
  bool met = false;
};

/// The one report of every benchmark's targets: a line per target ("met" or "MISSED", the
/// target, the measurement) and "N of M targets met"; "none checked" when there are none.
void printTargets(std::ostream& out, const std::vector<Target>& targets);

}  // namespace asr_common::cli
