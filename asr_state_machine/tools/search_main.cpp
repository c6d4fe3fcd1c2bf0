// `asr search` (the executable search): one active search in-process on simulated time.
#include <iomanip>
#include <iostream>
#include <sstream>

#include "asr_common/cli/command_line.hpp"
#include "asr_common/cli/command_main.hpp"
#include "asr_robot_model/world.hpp"
#include "asr_state_machine/in_process_search.hpp"
#include "asr_state_machine/search_json.hpp"
#include "asr_state_machine/search_picture.hpp"

namespace {

using namespace asr_state_machine;
using asr_common::cli::CommandLine;
using asr_common::cli::UsageError;

const char* const kUsage =
    "usage: asr search --world W --models M1[,M2..] [--scenes S1,S2..] [--required S:0.85,..]\n"
    "                  [--mode asr|direct|bbox] [--seed S] [--max-sim-minutes N]\n"
    "                  [--demonstrated F] [--catalogue K] [--json] [--png P]\n"
    "       asr search --world W --result R [--catalogue K] [--json] [--png P]\n"
    "  One active search for the objects of the scene models in a simulated world, in-process\n"
    "  on simulated time (docs/search.md). --mode asr (default): direct and indirect search;\n"
    "  direct: direct search only; bbox: next-best-view over the furniture, no scene knowledge.\n"
    "  --required: end when these scenes reach these confidences; --demonstrated: an objects\n"
    "  file of where the objects were demonstrated (direct search looks there first);\n"
    "  --max-sim-minutes defaults to 60. --png: a top-down picture of the search (room,\n"
    "  furniture, path, numbered views, objects found and missed). --result: the summary (or\n"
    "  JSON) and picture of a search saved with --json (or by the search_executive node)\n"
    "  instead of searching.\n"
    "  -> {\"outcome\", \"reason\", \"sim_seconds\", \"compute_seconds\", \"views\", \"found\": "
    "[{\"type\",\n"
    "      \"id\", \"pose\", \"found_at_s\", \"view\"}], \"scenes\": [{\"scene\", "
    "\"confidence\"}], "
    "\"log\": [...]};\n"
    "  without --json a summary.\n";

std::vector<std::string> commaList(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    if (!item.empty())
      items.push_back(item);
  }
  return items;
}

std::map<std::string, double> requiredScenes(const std::string& text) {
  std::map<std::string, double> required;
  for (const std::string& item : commaList(text)) {
    const std::size_t colon = item.rfind(':');
    if (colon == std::string::npos || colon == 0) {
      throw UsageError{"--required takes SCENE:CONFIDENCE items, not '" + item + "'"};
    }
    try {
      std::size_t used = 0;
      const std::string number = item.substr(colon + 1);
      required[item.substr(0, colon)] = std::stod(number, &used);
      if (used != number.size())
        throw std::invalid_argument(number);
    } catch (const std::exception&) {
      throw UsageError{"--required: '" + item + "' has no confidence number"};
    }
  }
  return required;
}

// Fixed decimals, for the summary's columns.
std::string fixed(double value, int digits) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(digits) << value;
  return text.str();
}

void printSummary(const SearchResult& result) {
  std::cout << "outcome: " << outcomeName(result.outcome)
            << (result.reason.empty() ? "" : " (" + result.reason + ")") << "\n"
            << "simulated: " << fixed(result.sim_seconds / 60.0, 2) << " min, "
            << result.world.visitedViews().size() << " views; compute "
            << fixed(result.compute_seconds, 3) << " s\n"
            << "found (simulated seconds, view):\n";
  for (const FoundObject& found : result.world.foundObjects()) {
    std::cout << "  " << std::left << std::setw(28) << found.key.toString() << std::right
              << std::setw(7) << fixed(found.found_at_s, 1) << " s  view " << found.view << "\n";
  }
  std::cout << "scenes:\n";
  for (const auto& [scene, objects] : result.world.sceneObjects()) {
    std::cout << "  " << std::left << std::setw(14) << scene << std::right << " confidence "
              << fixed(result.world.sceneConfidence(scene), 2) << ", "
              << objects.size() - result.world.missingObjects(scene).size() << " of "
              << objects.size() << " objects found\n";
  }
}

SearchResult searchOrRead(const CommandLine& options) {
  if (options.has("result"))
    return readSearchResult(options.required("result"));
  SearchRequest request;
  request.world = options.required("world");
  request.model_files = commaList(options.required("models"));
  request.scenes = commaList(options.optional("scenes", ""));
  request.demonstrated = options.optional("demonstrated", "");
  request.catalogue = options.optional("catalogue", "");
  request.config.mode = parseMode(options.optional("mode", "asr"));
  request.config.seed = static_cast<std::uint32_t>(options.integer("seed", 0, 0, 4294967295LL));
  const double minutes = options.number("max-sim-minutes", 60.0);
  if (!(minutes > 0.0))
    throw UsageError{"--max-sim-minutes must be positive"};
  request.config.max_sim_seconds = 60.0 * minutes;
  request.config.required_scenes = requiredScenes(options.optional("required", ""));

  InProcessSearch search(request);
  return search.run();
}

int run(const std::vector<std::string>& arguments) {
  const CommandLine options(arguments,
                            {"world", "models", "scenes", "required", "mode", "seed",
                             "max-sim-minutes", "demonstrated", "catalogue", "png", "result"},
                            {"json"});
  const std::string catalogue = options.optional("catalogue", "");
  const std::string world_file = options.required("world");
  if (options.has("png"))
    checkPictureFile(options.required("png"));
  const SearchResult result = searchOrRead(options);
  if (options.has("png")) {
    const asr_robot_model::World world = asr_robot_model::loadWorld(
        world_file, asr_robot_model::loadObjectCatalogue(
                        catalogue.empty() ? asr_robot_model::defaultObjectCatalogue() : catalogue));
    writeSearchPicture(world, result, options.required("png"));
  }
  if (options.flag("json")) {
    std::cout << searchResultJson(result).dump() << "\n";
  } else {
    printSummary(result);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return asr_common::cli::runToolMain("asr search", kUsage, run, argc, argv);
}
