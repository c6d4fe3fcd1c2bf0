// learn_kitchen_models: the kitchen's scene models, learned from the recordings without the set
// that places each scene in the kitchen world, and (--world-out) that world.
#include <fstream>
#include <iostream>

#include "asr_common/atomic_file.hpp"
#include "asr_common/cli/command_line.hpp"
#include "asr_common/cli/command_main.hpp"
#include "asr_common/input_error.hpp"
#include "asr_common/recordings.hpp"
#include "asr_state_machine/kitchen.hpp"

namespace {

const char* const kUsage =
    "usage: learn_kitchen_models --model OUT.sqlite [--recordings DIR] [--world-out W.yaml]\n"
    "  Learns star-topology ISM trees of the kitchen's scenes (gedeck, Brot_Regal,\n"
    "  Muesli_Regal) from the recordings, each without the set that places it in the kitchen\n"
    "  world; --world-out writes that world (asr_state_machine/config/worlds/kitchen.yaml).\n";

int run(const std::vector<std::string>& arguments) {
  const asr_common::cli::CommandLine options(arguments, {"model", "recordings", "world-out"}, {});
  const std::string recordings =
      asr_common::recordingsLocation(ASR_RECORDINGS_DIR, options.optional("recordings", ""));
  if (!asr_common::isDirectory(recordings)) {
    throw asr_common::InputError("the recordings folder '" + recordings + "' does not exist");
  }
  for (const std::string& line :
       asr_state_machine::kitchen::learnKitchenModels(recordings, options.required("model"))) {
    std::cout << "learned " << line << "\n";
  }
  if (options.has("world-out")) {
    const std::string path = options.required("world-out");
    asr_common::writeFileAtomically(path, asr_state_machine::kitchen::kitchenWorldYaml(recordings));
    std::cout << "wrote " << path << "\n";
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return asr_common::cli::runToolMain("learn_kitchen_models", kUsage, run, argc, argv);
}
