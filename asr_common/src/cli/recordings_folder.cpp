#include "asr_common/cli/recordings_folder.hpp"

#include "asr_common/recordings.hpp"

namespace asr_common::cli {

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
  const std::string given = options.has("recordings") ? options.required("recordings") : "";
  const std::string recordings = recordingsLocation(compiled_default, given);
  if (isDirectory(recordings))
    return recordings;
  progress << program << ": recordings folder '" << recordings
           << "' not found; skipping the kitchen scenes (give --recordings DIR or set "
              "ASR_RECORDINGS_DIR)\n";
  return std::nullopt;
}

}  // namespace asr_common::cli
