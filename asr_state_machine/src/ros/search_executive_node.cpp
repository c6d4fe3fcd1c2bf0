#include "asr_state_machine/ros/search_executive_node.hpp"

#include <asr_msgs/SearchLogEntry.h>
#include <std_msgs/String.h>
#include <visualization_msgs/MarkerArray.h>

#include "asr_common/input_error.hpp"
#include "asr_common/ros/node_parameters.hpp"
#include "asr_common/ros/queue_sizes.hpp"
#include "asr_ism/thread_pool.hpp"
#include "asr_state_machine/furniture_sweep.hpp"
#include "asr_state_machine/in_process_parts.hpp"
#include "asr_state_machine/ros/ros_parts.hpp"
#include "asr_state_machine/ros/search_markers.hpp"
#include "asr_state_machine/search_json.hpp"

namespace asr_state_machine::ros_interface {

namespace {

using namespace asr_common::ros_interface;

constexpr std::uint32_t kLogQueue = 1000;

std::map<std::string, double> requiredScenesParameter(const ros::NodeHandle& node) {
  std::map<std::string, double> required;
  if (node.hasParam("required_scenes") && !node.getParam("required_scenes", required)) {
    throw asr_common::InputError("parameter " + node.resolveName("required_scenes") +
                                 " must be a dictionary of scene: confidence");
  }
  return required;
}

}  // namespace

SearchExecutiveNode::SearchExecutiveNode(ros::NodeHandle node, ros::NodeHandle private_node)
    : node_(node), private_node_(private_node) {
  state_ = private_node_.advertise<std_msgs::String>("state", kLatchedQueue, true);
  result_ = private_node_.advertise<std_msgs::String>("result", kLatchedQueue, true);
  log_ = node_.advertise<asr_msgs::SearchLogEntry>("search_log", kLogQueue);
  markers_ =
      node_.advertise<visualization_msgs::MarkerArray>("search_markers", kLatchedQueue, true);
}

SearchRequest SearchExecutiveNode::readRequest() {
  const ros::NodeHandle& p = private_node_;
  SearchRequest request;
  request.world = requiredParameter<std::string>(p, "world");
  request.model_files = stringListParameter(p, "model_files");
  checkParameter(p, "model_files", !request.model_files.empty(),
                 "set to the model files to search with (a list, or one file)");
  request.scenes = stringListParameter(p, "scenes");
  request.demonstrated = optionalParameter<std::string>(p, "demonstrated", "");
  request.catalogue = optionalParameter<std::string>(p, "catalogue", "");
  try {
    request.config.mode = parseMode(optionalParameter<std::string>(p, "mode", "asr"));
  } catch (const asr_common::InputError& error) {
    throw asr_common::InputError("parameter " + p.resolveName("mode") + ": " + error.what());
  }
  request.config.seed = static_cast<std::uint32_t>(integerParameter(p, "seed", 0, 0, 4294967295LL));
  request.config.max_sim_seconds = 60.0 * numberParameter(p, "max_sim_minutes", 60.0, 1e-3, 1e6);
  request.config.required_scenes = requiredScenesParameter(p);
  frame_ = fixedFrameParameter(p);
  part_timeout_ = numberParameter(p, "part_timeout", 60.0, 0.1, 1e6);
  startup_timeout_ = numberParameter(p, "startup_timeout", 300.0, 0.1, 1e6);
  samples_ = static_cast<std::size_t>(integerParameter(p, "samples", 60, 1, 100000));
  best_instances_ = static_cast<std::size_t>(integerParameter(p, "best_instances", 3, 1, 1000));
  result_file_ = optionalParameter<std::string>(p, "result_file", "");
  const auto log_file = optionalParameter<std::string>(p, "log_file", "");
  if (!log_file.empty()) {
    log_file_.open(log_file, std::ios::trunc);
    if (!log_file_)
      throw asr_common::InputError("parameter " + p.resolveName("log_file") + ": cannot write '" +
                                   log_file + "'");
  }
  return request;
}

void SearchExecutiveNode::run() {
  std::unique_ptr<SearchInputs> inputs;
  try {
    inputs = loadSearchInputs(readRequest());
  } catch (const asr_common::InputError& error) {
    nlohmann::ordered_json refused = {{"outcome", "error"}, {"reason", error.what()}};
    publishResult("error", refused.dump());
    throw;
  }
  ROS_INFO("search_executive: %zu scenes, mode %s; waiting for the nodes",
           inputs->models.scenes().size(), modeName(inputs->config.mode));
  const SearchResult result = search(*inputs);
  ROS_INFO("search_executive: %s%s after %.1f simulated minutes, %zu views",
           outcomeName(result.outcome), result.reason.empty() ? "" : (": " + result.reason).c_str(),
           result.sim_seconds / 60.0, result.world.visitedViews().size());
  publishResult(outcomeName(result.outcome), searchResultJson(result).dump());
}

SearchResult SearchExecutiveNode::search(const SearchInputs& inputs) {
  const PartEndpoint robot_part{"robot_driver", part_timeout_};
  const PartEndpoint detector_part{"object_detector", part_timeout_};
  const PartEndpoint recognizer_part{"scene_recognizer", part_timeout_};
  const PartEndpoint predictor_part{"pose_predictor", part_timeout_};
  const PartEndpoint planner_part{"next_best_view", part_timeout_};
  auto publish = [&](const LogEntry& entry, const WorldModel& world) {
    publishEntry(entry, world, inputs);
  };
  try {
    waitForServices(detector_part, {"detect_objects"}, startup_timeout_);
    waitForServices(recognizer_part, {"recognize_scenes"}, startup_timeout_);
    if (inputs.config.mode != SearchMode::kBoundingBox)
      waitForServices(predictor_part, {"predict_poses"}, startup_timeout_);
    waitForServices(
        planner_part,
        {"set_nbv_hypotheses", "get_next_best_view", "update_nbv_hypotheses", "remove_nbv_objects"},
        startup_timeout_);
    RosRobot robot(node_, inputs.robot, robot_part, startup_timeout_);
    RosDetector detector(frame_, detector_part);
    std::map<std::string, std::vector<ObjectKey>> scene_objects;
    for (const std::string& scene : inputs.models.scenes())
      scene_objects[scene] = inputs.models.tree(scene).objects();
    RosRecognizer recognizer(scene_objects, inputs.models.scenes(), frame_, recognizer_part);
    // The bounding-box search has no scene knowledge: its hypotheses cover the furniture.
    std::unique_ptr<Predictor> predictor;
    if (inputs.config.mode == SearchMode::kBoundingBox)
      predictor = std::make_unique<FurniturePredictor>(inputs.world);
    else
      predictor = std::make_unique<RosPredictor>(samples_, best_instances_, frame_, predictor_part);
    RosViewPlanner planner(frame_, planner_part);
    FurnitureSweep direct_search(inputs.robot, inputs.world, *inputs.map, inputs.nbv.frustum,
                                 inputs.demonstrated);
    SearchExecutive executive({robot, detector, recognizer, *predictor, planner, direct_search},
                              inputs.config);
    executive.onLog(publish);
    return executive.run();
  } catch (const PartFailure& failure) {
    // Before the search began: a node never came up.
    SearchResult result;
    result.outcome = Outcome::kAborted;
    result.reason = failure.what();
    result.log.push_back({0.0, "INIT", outcomeName(result.outcome), result.reason, 0.0});
    publish(result.log.back(), result.world);
    return result;
  }
}

void SearchExecutiveNode::publishEntry(const LogEntry& entry, const WorldModel& world,
                                       const SearchInputs& inputs) {
  asr_msgs::SearchLogEntry message;
  message.header.stamp = ros::Time::now();
  message.header.frame_id = frame_;
  message.t = entry.t;
  message.state = entry.state;
  message.event = entry.event;
  message.detail = entry.detail;
  message.compute_ms = entry.compute_seconds * 1000.0;
  log_.publish(message);
  std_msgs::String state;
  state.data = entry.state;
  state_.publish(state);
  if (log_file_.is_open())
    log_file_ << logEntryJson(entry).dump() << std::endl;
  std_msgs::Header header;
  header.frame_id = frame_;
  header.stamp = message.header.stamp;
  markers_.publish(searchMarkers(world, inputs.nbv.frustum, header));
  ROS_INFO("search_executive: [%7.1f s] %s %s %s", entry.t, entry.state.c_str(),
           entry.event.c_str(), entry.detail.c_str());
}

void SearchExecutiveNode::publishResult(const std::string& outcome, const std::string& json) {
  std_msgs::String state;
  state.data = outcome;
  state_.publish(state);
  std_msgs::String result;
  result.data = json;
  result_.publish(result);
  if (!result_file_.empty()) {
    std::ofstream file(result_file_, std::ios::trunc);
    file << json << "\n";
    if (!file)
      ROS_ERROR("search_executive: cannot write the result to '%s'", result_file_.c_str());
  }
}

}  // namespace asr_state_machine::ros_interface
