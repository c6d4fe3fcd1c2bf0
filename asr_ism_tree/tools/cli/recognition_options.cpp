#include "asr_ism_tree/cli/recognition_options.hpp"

#include <cmath>
#include <sstream>

#include "asr_ism/input_limits.hpp"

namespace asr_ism_tree::cli {

using asr_common::cli::UsageError;

asr_ism::IsmRecognitionParameters recognitionParametersFrom(
    const asr_common::cli::CommandLine& options) {
  asr_ism::IsmRecognitionParameters parameters;
  parameters.bin_size = options.number("bin-size", parameters.bin_size);
  const double max_angle_deg = options.number("max-angle-deg", 30.0);
  if (!(parameters.bin_size >= asr_ism::kMinBinSize &&
        parameters.bin_size <= asr_ism::kMaxBinSize)) {
    std::ostringstream message;
    message << "--bin-size must be in [" << asr_ism::kMinBinSize << ", " << asr_ism::kMaxBinSize
            << "] m";
    throw UsageError{message.str()};
  }
  if (!(max_angle_deg > 0.0 && max_angle_deg <= 180.0))
    throw UsageError{"--max-angle-deg must be in (0, 180]"};
  parameters.max_angle_deviation = max_angle_deg * M_PI / 180.0;
  asr_ism::checkRecognitionParameters(parameters, "--bin-size, --max-angle-deg");
  return parameters;
}

}  // namespace asr_ism_tree::cli
