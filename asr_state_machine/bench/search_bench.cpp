// `asr bench search`: the paper's comparison on the kitchen: direct search only, bounding-box
// next-best-view search and Active Scene Recognition, over seeds (detection noise, start pose).
#include <unistd.h>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "asr_common/atomic_file.hpp"
#include "asr_common/cli/command_line.hpp"
#include "asr_common/cli/command_main.hpp"
#include "asr_common/cli/recordings_folder.hpp"
#include "asr_common/cli/targets.hpp"
#include "asr_common/cli/timing.hpp"
#include "asr_state_machine/in_process_search.hpp"
#include "asr_state_machine/kitchen.hpp"
#include "asr_state_machine/search_picture.hpp"
#include "comparison_plot.hpp"

namespace {

using namespace asr_state_machine;
using asr_common::cli::CommandLine;
using asr_common::cli::median;

// Recorded sets that place the scenes, one after another over the seeds.
constexpr std::size_t kPlacements = 5;

const char* const kUsage =
    "usage: asr bench search [--seeds N] [--world W] [--models M] [--recordings DIR] [--json]\n"
    "                        [--plot FILE.png]\n"
    "  Direct search only, bounding-box search and Active Scene Recognition on the kitchen\n"
    "  over N seeds (default 10): each seed changes the detection noise, the robot's start (up\n"
    "  to 0.3 m, 0.9 rad) and which of the last 5 complete recorded sets places each scene\n"
    "  (the models are learned without it); --world and --models fix world and models\n"
    "  (--world defaults to asr_state_machine/config/worlds/kitchen.yaml). A table of simulated "
    "minutes,\n"
    "  views and objects found beside the paper's figures, and the targets. --plot draws\n"
    "  median and range of the simulated minutes per mode beside the paper's (gnuplot).\n";

struct ModeRuns {
  SearchMode mode;
  double paper_minutes;
  std::vector<double> minutes, views, found, compute_ms;
  int all_found = 0;
};

std::string range(const std::vector<double>& values, int digits) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(digits) << median(values) << " ("
       << *std::min_element(values.begin(), values.end()) << "-"
       << *std::max_element(values.begin(), values.end()) << ")";
  return text.str();
}

// The modes as the paper names them.
std::string modeLabel(SearchMode mode) {
  switch (mode) {
    case SearchMode::kDirect:
      return "direct search only";
    case SearchMode::kBoundingBox:
      return "bounding-box NBV search";
    case SearchMode::kAsr:
      return "Active Scene Recognition";
  }
  return modeName(mode);
}

int run(const std::vector<std::string>& arguments) {
  const CommandLine options(arguments, {"seeds", "world", "models", "recordings", "plot"},
                            {"json"});
  const int seeds = static_cast<int>(options.integer("seeds", 10, 1, 1000));
  if (options.has("plot"))
    checkPictureFile(options.required("plot"));  // before the searches, not after
  const std::string folder =
      (std::filesystem::temp_directory_path() / ("asr_bench_search_" + std::to_string(getpid())))
          .string();
  // Per placement (which held-out recorded set places the scenes), a world and the models
  // learned without that set; or the given world and models for every seed.
  std::vector<std::string> worlds, models;
  if (options.has("models") || options.has("world")) {
    worlds = {options.optional(
        "world", std::string(ASR_STATE_MACHINE_SOURCE_DIR) + "/config/worlds/kitchen.yaml")};
    models = {options.required("models")};
  } else {
    const auto recordings = asr_common::cli::benchmarkRecordings(options, ASR_RECORDINGS_DIR,
                                                                 "asr bench search", std::cerr);
    if (!recordings)
      return 0;
    std::filesystem::create_directories(folder);
    for (std::size_t placement = 0; placement < kPlacements; ++placement) {
      const std::string suffix = std::to_string(placement);
      models.push_back(folder + "/kitchen_models_" + suffix + ".sqlite");
      kitchen::learnKitchenModels(*recordings, models.back(), placement);
      worlds.push_back(folder + "/kitchen_" + suffix + ".yaml");
      asr_common::writeFileAtomically(worlds.back(),
                                      kitchen::kitchenWorldYaml(*recordings, placement));
    }
  }

  // The paper's simulation: minutes until all objects were found.
  std::vector<ModeRuns> runs = {{SearchMode::kDirect, 31.13, {}, {}, {}, {}, 0},
                                {SearchMode::kBoundingBox, 15.24, {}, {}, {}, {}, 0},
                                {SearchMode::kAsr, 2.48, {}, {}, {}, {}, 0}};
  std::vector<double> asr_decisions_ms;
  for (ModeRuns& mode : runs) {
    for (int seed = 0; seed < seeds; ++seed) {
      SearchRequest request;
      request.world = worlds[seed % worlds.size()];
      request.model_files = {models[seed % models.size()]};
      request.config.mode = mode.mode;
      request.config.seed = static_cast<std::uint32_t>(seed);
      request.config.max_sim_seconds = 3 * 3600.0;
      request.start_jitter = 0.3;
      const SearchResult result = InProcessSearch(request).run();
      mode.minutes.push_back(result.sim_seconds / 60.0);
      mode.views.push_back(static_cast<double>(result.world.visitedViews().size()));
      mode.found.push_back(static_cast<double>(result.world.foundObjects().size()));
      if (result.outcome == Outcome::kFoundAllObjects)
        ++mode.all_found;
      mode.compute_ms.push_back(1000.0 * median(result.decision_compute_seconds));
      if (mode.mode == SearchMode::kAsr) {
        for (double s : result.decision_compute_seconds)
          asr_decisions_ms.push_back(1000.0 * s);
      }
      std::cerr << modeName(mode.mode) << " seed " << seed << ": " << outcomeName(result.outcome)
                << ", " << result.sim_seconds / 60.0 << " min, "
                << result.world.visitedViews().size() << " views\n";
    }
  }
  std::filesystem::remove_all(folder);

  if (options.has("plot")) {
    std::vector<asr_state_machine::bench::ModeMinutes> plotted;
    for (const ModeRuns& mode : runs)
      plotted.push_back({modeLabel(mode.mode), mode.minutes, mode.paper_minutes});
    asr_state_machine::bench::plotComparison(plotted, seeds, options.required("plot"));
    std::cerr << "plot written to " << options.required("plot") << "\n";
  }

  const ModeRuns& direct = runs[0];
  const ModeRuns& bbox = runs[1];
  const ModeRuns& asr = runs[2];
  const double decision_ms = median(asr_decisions_ms);
  std::vector<asr_common::cli::Target> targets = {
      {"every ASR run finds all objects",
       std::to_string(asr.all_found) + " of " + std::to_string(seeds), asr.all_found == seeds},
      {"ASR median <= 1/5 of direct search only",
       std::to_string(median(asr.minutes) / median(direct.minutes)),
       median(asr.minutes) <= median(direct.minutes) / 5.0},
      {"ASR median <= 1/2 of bounding-box search",
       std::to_string(median(asr.minutes) / median(bbox.minutes)),
       median(asr.minutes) <= median(bbox.minutes) / 2.0},
      {"ASR compute per decision <= 50 ms median", std::to_string(decision_ms) + " ms",
       decision_ms <= 50.0}};

  if (options.flag("json")) {
    nlohmann::ordered_json out;
    out["seeds"] = seeds;
    for (const ModeRuns& mode : runs) {
      out["modes"].push_back({{"mode", modeName(mode.mode)},
                              {"minutes", mode.minutes},
                              {"views", mode.views},
                              {"found", mode.found},
                              {"all_found", mode.all_found},
                              {"paper_minutes", mode.paper_minutes}});
    }
    out["asr_decision_ms_median"] = decision_ms;
    for (const auto& target : targets) {
      out["targets"].push_back(
          {{"target", target.target}, {"measured", target.measured}, {"met", target.met}});
    }
    std::cout << out.dump() << "\n";
    return 0;
  }
  std::cout << "| mode | simulated minutes, median (range) | views | objects found | all found | "
               "paper (min) |\n|---|---|---|---|---|---|\n";
  for (const ModeRuns& mode : runs) {
    std::cout << "| " << modeName(mode.mode) << " | " << range(mode.minutes, 2) << " | "
              << range(mode.views, 0) << " | " << range(mode.found, 0) << " | " << mode.all_found
              << " of " << seeds << " | " << mode.paper_minutes << " |\n";
  }
  std::cout << "ASR compute per decision (recognition, prediction, next-best-view): median "
            << decision_ms << " ms over " << asr_decisions_ms.size() << " decisions\n";
  asr_common::cli::printTargets(std::cout, targets);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return asr_common::cli::runToolMain("asr bench search", kUsage, run, argc, argv);
}
