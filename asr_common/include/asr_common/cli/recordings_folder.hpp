#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "asr_common/cli/command_line.hpp"

namespace asr_common::cli {

/// The recordings folder a benchmark reads (`--recordings DIR`, which the command must declare,
/// else as recordingsLocation says) if it exists; otherwise says on `progress` that `program` skips
/// the kitchen scenes and how to point it at the recordings, and returns nothing.
std::optional<std::string> benchmarkRecordings(const CommandLine& options,
                                               const std::string& compiled_default,
                                               const std::string& program, std::ostream& progress);

/// The ten kitchen scenes of the paper's evaluation: file (in the recordings folder) and scene.
struct KitchenScene {
  const char* file;
  const char* scene;
};
const std::vector<KitchenScene>& kitchenScenes();

}  // namespace asr_common::cli
