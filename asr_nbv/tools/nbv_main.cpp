// `asr nbv` (the executable nbv): the next best view for predicted clouds in a world.
#include <iostream>
#include <sstream>

#include "asr_common/cli/command_line.hpp"
#include "asr_common/cli/command_main.hpp"
#include "asr_common/cli/timing.hpp"
#include "asr_nbv/nbv_documents.hpp"
#include "asr_nbv/next_best_view_planner.hpp"
#include "asr_robot_model/world.hpp"
#include "nbv_json.hpp"

namespace {

using namespace asr_nbv;
using asr_common::cli::CommandLine;

const char* const kUsage =
    "usage: asr nbv --world W --clouds C.json [--state \"x y yaw pan tilt\"] [--visited V.json]\n"
    "               [--seed S] [--threads N] [--config P] [--urdf U] [--catalogue K] [--json]\n"
    "  The camera view the robot should move to next to find the predicted objects\n"
    "  (docs/next_best_view.md). C.json is the output of `asr ism predict --json` or a list of\n"
    "  such documents; V.json the views already taken, [{\"camera\": pose, \"types\": [...]}].\n"
    "  --state defaults to the world's robot; poses are camera_optical_frame in map; --config\n"
    "  defaults to asr_nbv/config/next_best_view.yaml; --threads 0 (default) uses every core.\n"
    "  -> {\"found\", \"view\": {\"camera\", \"state\", \"types\"}, \"utility\", \"rating\",\n"
    "      \"costs\": {...}, \"candidates_rated\", \"runtime_ms\", \"hypotheses\", "
    "\"rejected_poses\",\n"
    "      \"warnings\"}; --json prints one line, else the same JSON indented.\n";

int run(const std::vector<std::string>& arguments) {
  const CommandLine options(
      arguments,
      {"world", "clouds", "state", "visited", "seed", "threads", "config", "urdf", "catalogue"},
      {"json"});
  const std::string world_file = options.required("world");
  const std::string clouds_file = options.required("clouds");
  const NbvParameters parameters =
      loadNbvParameters(options.optional("config", defaultNbvParameters()));
  const asr_robot_model::ObjectCatalogue catalogue = asr_robot_model::loadObjectCatalogue(
      options.optional("catalogue", asr_robot_model::defaultObjectCatalogue()));
  const asr_robot_model::World world = asr_robot_model::loadWorld(world_file, catalogue);
  const asr_robot_model::RobotDescription robot = asr_robot_model::loadRobotDescription(
      options.optional("urdf", asr_robot_model::defaultRobotUrdf()));
  const asr_robot_model::RobotState state = tools::stateOption(options, "state", world.robot);
  const unsigned seed = static_cast<unsigned>(options.integer("seed", 0, 0, 4294967295LL));
  const unsigned threads = static_cast<unsigned>(options.integer("threads", 0, 0, 256));

  HypothesisSet hypotheses(readPredictedClouds(clouds_file), catalogue);
  const asr_robot_model::WorldMap map(world, parameters.occlusion_resolution, robot.base_radius);
  if (options.has("visited")) {
    for (const VisitedView& view : readVisitedViews(options.required("visited")))
      updateAfterView(hypotheses, view.camera, view.types, parameters, &map);
  }
  for (const std::string& warning : hypotheses.warnings())
    std::cerr << "asr nbv: warning: " << warning << "\n";

  asr_ism::ThreadPool pool(threads);
  const NextBestViewPlanner planner(robot, world, map, parameters, &pool, seed);
  PlannedView view;
  const double milliseconds =
      asr_common::cli::millisecondsOf([&] { view = planner.plan(hypotheses, state); });
  nlohmann::ordered_json out = tools::plannedViewJson(view);
  out["runtime_ms"] = milliseconds;
  out["hypotheses"] = hypotheses.hypotheses().size();
  out["rejected_poses"] = hypotheses.rejectedPoses();
  out["warnings"] = hypotheses.warnings();
  std::cout << (options.flag("json") ? out.dump() : out.dump(2)) << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return asr_common::cli::runToolMain("asr nbv", kUsage, run, argc, argv);
}
