#include "asr_ism_tree/cli/recognition_options.hpp"

#include <cmath>

namespace asr_ism_tree::cli {

using asr_common::cli::UsageError;

asr_ism::IsmRecognitionParameters recognitionParametersFrom(
    const asr_common::cli::CommandLine& options) {
  asr_ism::IsmRecognitionParameters parameters;
  parameters.bin_size = options.number("bin-size", parameters.bin_size);
  const double max_angle_deg = options.number("max-angle-deg", 30.0);
  if (!(parameters.bin_size > 0.0))
    throw UsageError{"--bin-size must be > 0"};
  if (!(max_angle_deg > 0.0 && max_angle_deg <= 180.0))
    throw UsageError{"--max-angle-deg must be in (0, 180]"};
  parameters.max_angle_deviation = max_angle_deg * M_PI / 180.0;
  return parameters;
}

}  // namespace asr_ism_tree::cli
