#pragma once

#include <string>
#include <vector>

#include "runtime_benchmark.hpp"

namespace asr_pose_prediction::bench {

/// Draws the synthetic runtime rows like the paper's figure of prediction runtimes: median time
/// against the number of objects, one curve per demonstration length (complete trees solid, star
/// trees dashed), as a PNG at `path`. gnuplot (pngcairo) draws into a temporary file beside it,
/// which is renamed into place, so an existing plot is replaced whole or not at all. Throws
/// InputError if gnuplot is missing or fails, or the file cannot be written.
void plotSyntheticRuntime(const std::vector<RuntimeRow>& rows, const std::string& path);

}  // namespace asr_pose_prediction::bench
