#pragma once

#include <string>
#include <vector>

namespace asr_state_machine::bench {

/// One search mode's simulated minutes over the seeds, and the paper's figure for it.
struct ModeMinutes {
  std::string name;
  std::vector<double> minutes;  // not empty
  double paper_minutes = 0.0;
};

/// The comparison as a plot (gnuplot, PNG at `path`): per mode the median, fastest and slowest
/// run's simulated minutes beside the paper's figure. Throws asr_common::InputError if it
/// cannot be drawn or written.
void plotComparison(const std::vector<ModeMinutes>& modes, int seeds, const std::string& path);

}  // namespace asr_state_machine::bench
