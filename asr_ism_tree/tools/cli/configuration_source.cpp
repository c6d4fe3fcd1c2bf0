#include "asr_ism_tree/cli/configuration_source.hpp"

#include <limits>

#include "asr_common/input_error.hpp"
#include "asr_ism/configuration_file.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"

namespace asr_ism_tree::cli {

using asr_common::cli::UsageError;

asr_common::Configuration loadConfiguration(const asr_common::cli::CommandLine& options,
                                            const std::string& scene) {
  if (options.has("objects") == options.has("demo")) {
    throw UsageError{"give either --objects FILE or --demo DB --set K"};
  }
  if (options.has("objects")) {
    if (options.has("set"))
      throw UsageError{"--set goes with --demo, not --objects"};
    return asr_ism::readConfigurationFile(options.required("objects"));
  }
  const std::string demo_path = options.required("demo");
  if (!options.has("set"))
    throw UsageError{"--demo needs --set K"};
  const long long set = options.integer("set", 0, 0, std::numeric_limits<long long>::max());
  const asr_ism::Demonstration demonstration = asr_ism::sqlite::readDemonstration(demo_path, scene);
  if (static_cast<std::size_t>(set) >= demonstration.stepCount()) {
    throw asr_common::InputError(
        demo_path + ": scene '" + scene + "' has " + std::to_string(demonstration.stepCount()) +
        " recorded sets; set " + std::to_string(set) + " does not exist (sets count from 0)");
  }
  return demonstration.configuration(static_cast<std::size_t>(set));
}

}  // namespace asr_ism_tree::cli
