#pragma once

#include "asr_common/cli/command_line.hpp"
#include "asr_ism/ism_recognizer.hpp"

namespace asr_ism_tree::cli {

/// The options --bin-size M and --max-angle-deg D (defaults 0.1 m, 30 degrees), checked: throws
/// UsageError for values out of range.
asr_ism::IsmRecognitionParameters recognitionParametersFrom(
    const asr_common::cli::CommandLine& options);

}  // namespace asr_ism_tree::cli
