#include "asr_common/cli/recordings_folder.hpp"

#include <sys/stat.h>

#include <cstdlib>

namespace asr_common::cli {

std::string recordingsFolder(const CommandLine& options, const std::string& compiled_default) {
  if (options.has("recordings"))
    return options.required("recordings");
  const char* from_environment = std::getenv("ASR_RECORDINGS_DIR");
  return from_environment != nullptr ? from_environment : compiled_default;
}

bool isDirectory(const std::string& path) {
  struct stat info;
  return stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode);
}

const std::vector<KitchenScene>& kitchenScenes() {
  static const std::vector<KitchenScene> scenes = {
      {"story_1.sqlite", "gedeck"},           {"story_1.sqlite", "Gedeck_Ende"},
      {"story_1.sqlite", "Gedeck_Schrank_2"}, {"story_1.sqlite", "Spuelkorb_3"},
      {"story_2.sqlite", "Brot_Gedeck_2"},    {"story_2.sqlite", "Brot_Regal"},
      {"story_2.sqlite", "Getraenke_Gedeck"}, {"story_2.sqlite", "Getraenke_Regal"},
      {"story_2.sqlite", "Muesli_Gedeck"},    {"story_2.sqlite", "Muesli_Regal"},
  };
  return scenes;
}

std::optional<std::string> benchmarkRecordings(const CommandLine& options,
                                               const std::string& compiled_default,
                                               const std::string& program, std::ostream& progress) {
  const std::string recordings = recordingsFolder(options, compiled_default);
  if (isDirectory(recordings))
    return recordings;
  progress << program << ": recordings folder '" << recordings
           << "' not found; skipping the kitchen scenes (give --recordings DIR or set "
              "ASR_RECORDINGS_DIR)\n";
  return std::nullopt;
}

}  // namespace asr_common::cli
