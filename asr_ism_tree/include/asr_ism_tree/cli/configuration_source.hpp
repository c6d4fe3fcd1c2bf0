#pragma once

#include <string>

#include "asr_common/cli/command_line.hpp"
#include "asr_common/object.hpp"

namespace asr_ism_tree::cli {

/// The object configuration a command works on: `--objects FILE` (YAML or JSON), or the K-th
/// recorded set (0-based, by id) of `scene` with `--demo DB --set K`. Throws UsageError for
/// neither or both, InputError naming the file for a bad file or a set that does not exist.
/// The command must declare the options objects, demo and set.
asr_common::Configuration loadConfiguration(const asr_common::cli::CommandLine& options,
                                            const std::string& scene);

}  // namespace asr_ism_tree::cli
