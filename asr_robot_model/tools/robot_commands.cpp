#include "robot_commands.hpp"

#include <iostream>
#include <optional>
#include <sstream>

#include "asr_common/cli/command_line.hpp"
#include "asr_robot_model/detection_simulator.hpp"
#include "asr_robot_model/forward_kinematics.hpp"
#include "asr_robot_model/inverse_kinematics.hpp"
#include "asr_robot_model/world.hpp"
#include "asr_robot_model/world_map.hpp"
#include "robot_json.hpp"

namespace asr_robot_model::tools {

using asr_common::cli::CommandLine;

namespace {

RobotDescription robotOf(const CommandLine& options) {
  return loadRobotDescription(options.optional("urdf", defaultRobotUrdf()));
}

std::optional<World> worldOf(const CommandLine& options) {
  if (!options.has("world"))
    return std::nullopt;
  return loadWorld(options.required("world"),
                   loadObjectCatalogue(options.optional("catalogue", defaultObjectCatalogue())));
}

void print(const CommandLine& options, const nlohmann::json& result) {
  std::cout << (options.flag("json") ? result.dump() : result.dump(2)) << "\n";
}

std::vector<std::string> typeList(const std::string& text) {
  std::vector<std::string> types;
  std::istringstream list(text);
  for (std::string type; std::getline(list, type, ',');)
    if (!type.empty())
      types.push_back(type);
  return types;
}

}  // namespace

int runFk(const std::vector<std::string>& arguments) {
  const CommandLine options(arguments, {"urdf", "state"}, {"json"});
  const RobotDescription robot = robotOf(options);
  const RobotState state = stateOption(options, "state", RobotState{});
  print(options, {{"camera", poseJson(cameraPose(robot, state))}});
  return 0;
}

int runIk(const std::vector<std::string>& arguments) {
  const CommandLine options(
      arguments, {"urdf", "world", "catalogue", "camera", "from", "resolution"}, {"json"});
  const RobotDescription robot = robotOf(options);
  const std::optional<World> world = worldOf(options);
  Eigen::Vector3d position;
  Eigen::Quaterniond orientation;
  poseOption(options, "camera", position, orientation);
  const RobotState from = stateOption(options, "from", world ? world->robot : RobotState{});
  std::optional<WorldMap> map;
  BaseIsFree base_is_free;
  if (world) {
    map.emplace(*world, options.number("resolution", 0.02), robot.base_radius);
    base_is_free = [&map](double x, double y, double) { return map->baseIsFree(x, y); };
  }
  const InverseKinematics ik(robot, speedsOf(robot));
  const IkResult result = ik.solve(position, orientation, from, base_is_free);
  nlohmann::json out = {{"reachable", result.reachable},
                        {"reason", refusalName(result.reason)},
                        {"explanation", result.explanation}};
  if (result.reachable) {
    out["state"] = stateJson(result.state);
    out["camera"] = poseJson(result.camera);
    out["seconds"] = result.seconds;
    out["roll_difference"] = result.roll_difference;
  }
  print(options, out);
  return 0;
}

int runDetect(const std::vector<std::string>& arguments) {
  const CommandLine options(
      arguments, {"urdf", "world", "catalogue", "camera", "types", "resolution", "seed"}, {"json"});
  const RobotDescription robot = robotOf(options);
  options.required("world");  // a usage error without it
  const World world = *worldOf(options);
  Eigen::Vector3d position;
  Eigen::Quaterniond orientation;
  poseOption(options, "camera", position, orientation);
  const asr_common::Pose camera = asr_common::validatedPose(position, orientation, "--camera");
  const WorldMap map(world, options.number("resolution", 0.02), robot.base_radius);
  DetectionSimulator simulator(world, map, DetectionSettings{},
                               static_cast<unsigned>(options.integer("seed", 0, 0, 4294967295LL)));
  const Detections detections = simulator.detect(camera, typeList(options.optional("types", "")));
  nlohmann::json detected = nlohmann::json::array(), rejected = nlohmann::json::array();
  for (const auto& estimate : detections.detected)
    detected.push_back(
        {{"type", estimate.key.type}, {"id", estimate.key.id}, {"pose", poseJson(estimate.pose)}});
  for (const auto& object : detections.rejected)
    rejected.push_back(
        {{"type", object.key.type}, {"id", object.key.id}, {"why", rejectionName(object.why)}});
  print(options, {{"detected", detected}, {"rejected", rejected}, {"seconds", detections.seconds}});
  return 0;
}

}  // namespace asr_robot_model::tools
