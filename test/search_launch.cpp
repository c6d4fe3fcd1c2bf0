#include "search_launch.hpp"

#include <gtest/gtest.h>
#include <ros/master.h>
#include <ros/network.h>
#include <unistd.h>
#include <xmlrpcpp/XmlRpcClient.h>

#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>

#include "asr_common/testing/rostest_support.hpp"
#include "asr_state_machine/kitchen.hpp"

namespace asr_integration_tests {

namespace {

std::string temporaryFolder() {
  static const std::string folder = [] {
    const auto path = std::filesystem::temp_directory_path() /
                      ("asr_integration_tests_" + std::to_string(::getpid()));
    std::filesystem::create_directories(path);
    return path.string();
  }();
  return folder;
}

}  // namespace

std::string kitchenModels() {
  static std::once_flag learned;
  const std::string models = temporaryFolder() + "/kitchen_models.sqlite";
  std::call_once(
      learned, [&] { asr_state_machine::kitchen::learnKitchenModels(ASR_RECORDINGS_DIR, models); });
  return models;
}

std::string testFile(const std::string& name) {
  return std::string(ASR_INTEGRATION_TESTS_DIR) + "/" + name;
}

std::string kitchenWorld() {
  return std::string(ASR_INTEGRATION_TESTS_DIR) +
         "/../asr_state_machine/config/worlds/kitchen.yaml";
}

SearchLaunch::SearchLaunch(const std::string& name, const std::vector<std::string>& arguments)
    : log_(temporaryFolder() + "/" + name + "_roslaunch.log") {
  result_subscriber_ = node_.subscribe<std_msgs::String>(
      "search_executive/result", 1,
      [this](const std_msgs::StringConstPtr& message) { result_ = message->data; });
  state_subscriber_ = node_.subscribe<std_msgs::String>(
      "search_executive/state", 10, [this](const std_msgs::StringConstPtr& message) {
        state_ = message->data;
        states_.push_back(message->data);
      });
  std::vector<std::string> all = {"asr_state_machine", "search.launch", "rviz:=false"};
  all.insert(all.end(), arguments.begin(), arguments.end());
  launch_ = std::make_unique<asr_common::ChildProcess>("/usr/bin/roslaunch", all, log_, log_);
}

SearchLaunch::~SearchLaunch() {
  launch_->stop(std::chrono::seconds(30));
}

bool SearchLaunch::waitForState(const std::string& state, double guard_seconds) {
  return asr_common::testing::waitFor(
      [&] { return std::count(states_.begin(), states_.end(), state) > 0; }, guard_seconds);
}

std::optional<nlohmann::json> SearchLaunch::waitForResult(double guard_seconds) {
  if (!asr_common::testing::waitFor([&] { return result_.has_value(); }, guard_seconds))
    return std::nullopt;
  return nlohmann::json::parse(*result_);
}

std::string SearchLaunch::logTail() const {
  std::ifstream file(log_);
  std::vector<std::string> lines;
  for (std::string line; std::getline(file, line);)
    lines.push_back(line);
  std::ostringstream tail;
  for (std::size_t i = lines.size() > 30 ? lines.size() - 30 : 0; i < lines.size(); ++i)
    tail << lines[i] << "\n";
  return tail.str();
}

std::optional<int> nodePid(const std::string& node) {
  XmlRpc::XmlRpcValue request, response, payload;
  request[0] = ros::this_node::getName();
  request[1] = node;
  if (!ros::master::execute("lookupNode", request, response, payload, false))
    return std::nullopt;
  const std::string uri = payload;
  std::string host;
  std::uint32_t port = 0;
  if (!ros::network::splitURI(uri, host, port))
    return std::nullopt;
  XmlRpc::XmlRpcClient client(host.c_str(), static_cast<int>(port), "/");
  XmlRpc::XmlRpcValue arguments, answer;
  arguments[0] = ros::this_node::getName();
  if (!client.execute("getPid", arguments, answer) ||
      answer.getType() != XmlRpc::XmlRpcValue::TypeArray || answer.size() < 3 ||
      static_cast<int>(answer[0]) != 1)
    return std::nullopt;
  return static_cast<int>(answer[2]);
}

}  // namespace asr_integration_tests
