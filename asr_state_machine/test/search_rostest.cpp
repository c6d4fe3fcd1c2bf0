// The whole graph of search.launch on the kitchen (rostest, search.test): the search_executive over
// the simulated robot, detector, scene_recognizer, pose_predictor and next_best_view ends
// found_all_objects; every scene object is found where the world has it; the published summary
// is what `asr search --json` gives (same fields), its log is the JSON-lines log file, and the
// latched state says the outcome. A service call of a part ends in a PartFailure naming the
// node when the service is gone, stalls or fails every attempt; a call that fails is made again. search_bad_input.test: a scene no model holds is
// refused before anything moves, on ~result. Waits are wall-clock hang guards only: the search
// runs on simulated time.
#include <asr_msgs/ResetNbvHypotheses.h>
#include <asr_msgs/RobotState.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <std_msgs/String.h>

#include <atomic>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>

#include "asr_common/testing/rostest_support.hpp"
#include "asr_ism_tree/scene_models.hpp"
#include "asr_robot_model/robot_description.hpp"
#include "asr_robot_model/world.hpp"
#include "asr_state_machine/ros/timed_service_call.hpp"

namespace asr_state_machine {
namespace {

using asr_common::testing::waitFor;

// A hang guard, far beyond the search's few seconds on a loaded 2-core machine.
constexpr double kHangGuardSeconds = 600.0;

std::string privateParameter(const std::string& name) {
  std::string value;
  EXPECT_TRUE(ros::NodeHandle("~").getParam(name, value)) << name;
  return value;
}

class SearchLaunchTest : public ::testing::Test {
 protected:
  void SetUp() override {
    result_subscriber_ = node_.subscribe<std_msgs::String>(
        "search_executive/result", 1,
        [this](const std_msgs::StringConstPtr& message) { result_ = message->data; });
    state_subscriber_ = node_.subscribe<std_msgs::String>(
        "search_executive/state", 1,
        [this](const std_msgs::StringConstPtr& message) { state_ = message->data; });
    ASSERT_TRUE(waitFor([this] { return result_.has_value(); }, kHangGuardSeconds))
        << "no result from search_executive; last state: " << state_.value_or("(none)");
    summary_ = nlohmann::json::parse(*result_);
  }

  ros::NodeHandle node_;
  ros::Subscriber result_subscriber_, state_subscriber_;
  std::optional<std::string> result_, state_;
  nlohmann::json summary_;
};

TEST_F(SearchLaunchTest, TheKitchenIsSearchedUntilEveryObjectIsFound) {
  ASSERT_EQ(summary_["outcome"], "found_all_objects") << summary_.dump(1);
  EXPECT_EQ(summary_["reason"], "");
  EXPECT_GT(summary_["sim_seconds"].get<double>(), 0.0);
  EXPECT_GT(summary_["views"].get<int>(), 0);
  ASSERT_TRUE(waitFor([this] { return state_ == "found_all_objects"; }, 30.0)) << *state_;

  // Every object of every scene found, each where the world has it (the detector's noise is
  // millimetres; merging keeps it so).
  const auto catalogue =
      asr_robot_model::loadObjectCatalogue(asr_robot_model::defaultObjectCatalogue());
  const asr_robot_model::World world =
      asr_robot_model::loadWorld(privateParameter("world"), catalogue);
  const auto models = asr_ism_tree::SceneModels::load({privateParameter("model_files")}, {});
  std::set<std::string> found_keys;
  for (const auto& found : summary_["found"]) {
    const asr_common::ObjectKey key{found["type"], found["id"]};
    found_keys.insert(key.toString());
    const auto& p = found["pose"]["position"];
    const Eigen::Vector3d position(p["x"], p["y"], p["z"]);
    double nearest = 1e9;
    for (const asr_robot_model::WorldObject& object : world.objects) {
      if (object.key == key)
        nearest = std::min(nearest, (object.box.pose.position - position).norm());
    }
    EXPECT_LT(nearest, 0.05) << key.toString() << " found away from where the world has it";
    EXPECT_GE(found["view"].get<int>(), 0);
    EXPECT_LE(found["found_at_s"].get<double>(), summary_["sim_seconds"].get<double>());
  }
  for (const std::string& scene : models.scenes()) {
    for (const asr_common::ObjectKey& key : models.tree(scene).objects())
      EXPECT_TRUE(found_keys.count(key.toString())) << scene << ": " << key.toString();
  }
  for (const auto& scene : summary_["scenes"]) {
    EXPECT_GT(scene["confidence"].get<double>(), 0.0) << scene["scene"];
  }
}

TEST_F(SearchLaunchTest, TheLogFileHoldsEveryDecisionOfThePublishedLog) {
  const nlohmann::json& log = summary_["log"];
  ASSERT_FALSE(log.empty());
  EXPECT_EQ(log.front()["state"], "INIT");
  EXPECT_EQ(log.back()["event"], summary_["outcome"]);
  std::ifstream file(privateParameter("log_file"));
  ASSERT_TRUE(file.good()) << privateParameter("log_file");
  std::vector<nlohmann::json> lines;
  for (std::string line; std::getline(file, line);)
    lines.push_back(nlohmann::json::parse(line));
  ASSERT_EQ(lines.size(), log.size());
  double previous = 0.0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    EXPECT_EQ(lines[i], log[i]) << "entry " << i;
    EXPECT_GE(lines[i]["t"].get<double>(), previous) << "simulated time runs backwards at " << i;
    previous = lines[i]["t"];
  }
}

// Any service will do: the test's own, which stalls for as long as it is told to and fails the
// first `failures_` calls (roscpp's client sees a failed call as it sees a broken connection).
class PartCalls : public ::testing::Test {
 protected:
  void SetUp() override {
    spinner_.start();
    service_ = node_.advertiseService<asr_msgs::ResetNbvHypotheses::Request,
                                      asr_msgs::ResetNbvHypotheses::Response>(
        "stalling_service", [this](auto&, auto& response) {
          ros::WallDuration(stall_seconds_).sleep();
          response.hypotheses = 7;
          return ++calls_ > failures_;
        });
  }

  ros::NodeHandle node_;
  ros::AsyncSpinner spinner_{1};
  ros::ServiceServer service_;
  double stall_seconds_ = 0.0;
  std::atomic<int> calls_{0};
  int failures_ = 0;
};

TEST_F(PartCalls, ACallThatFailsWhileTheServiceIsOfferedIsMadeAgain) {
  failures_ = ros_interface::kServiceCallAttempts - 1;
  asr_msgs::ResetNbvHypotheses call;
  ros_interface::callService({"test_node", 30.0}, "stalling_service", call);
  EXPECT_EQ(call.response.hypotheses, 7u);
  EXPECT_EQ(calls_, ros_interface::kServiceCallAttempts);
}

TEST_F(PartCalls, ANodeThatFailsEveryAttemptIsAPartFailureNamingIt) {
  failures_ = 1000;
  asr_msgs::ResetNbvHypotheses call;
  try {
    ros_interface::callService({"test_node", 30.0}, "stalling_service", call);
    FAIL() << "no PartFailure";
  } catch (const PartFailure& failure) {
    EXPECT_EQ(failure.part(), "test_node");
    EXPECT_NE(std::string(failure.what()).find("failed 3 times"), std::string::npos)
        << failure.what();
  }
  EXPECT_EQ(calls_, ros_interface::kServiceCallAttempts);
  EXPECT_EQ(call.response.hypotheses, 0u) << "a failed call must leave the response as it was";
}

TEST_F(PartCalls, AnAnswerInTimeIsReturned) {
  asr_msgs::ResetNbvHypotheses call;
  ros_interface::callService({"test_node", 30.0}, "stalling_service", call);
  EXPECT_EQ(call.response.hypotheses, 7u);
}

TEST_F(PartCalls, AStalledNodeIsAPartFailureNamingIt) {
  stall_seconds_ = 3.0;
  asr_msgs::ResetNbvHypotheses call;
  try {
    ros_interface::callService({"test_node", 0.5}, "stalling_service", call);
    FAIL() << "no PartFailure";
  } catch (const PartFailure& failure) {
    EXPECT_EQ(failure.part(), "test_node");
    EXPECT_NE(std::string(failure.what()).find("did not answer within"), std::string::npos)
        << failure.what();
  }
}

TEST_F(PartCalls, AServiceThatIsGoneIsAPartFailureNamingIt) {
  asr_msgs::ResetNbvHypotheses call;
  try {
    ros_interface::callService({"nowhere", 30.0}, "no_such_service", call);
    FAIL() << "no PartFailure";
  } catch (const PartFailure& failure) {
    EXPECT_EQ(failure.part(), "nowhere");
    EXPECT_NE(std::string(failure.what()).find("is gone"), std::string::npos) << failure.what();
  }
}

// search_bad_input.test: scenes:=[lunch], which no model holds.
TEST(BadInput, ASceneNoModelHoldsIsRefusedBeforeAnythingMoves) {
  ros::NodeHandle node;
  std::optional<std::string> result;
  std::optional<asr_msgs::RobotState> start;
  ros::Subscriber result_subscriber = node.subscribe<std_msgs::String>(
      "search_executive/result", 1,
      [&](const std_msgs::StringConstPtr& message) { result = message->data; });
  ASSERT_TRUE(waitFor([&] { return result.has_value(); }, kHangGuardSeconds));
  const nlohmann::json refused = nlohmann::json::parse(*result);
  EXPECT_EQ(refused["outcome"], "error");
  EXPECT_NE(refused["reason"].get<std::string>().find("'lunch'"), std::string::npos) << *result;
  // The robot is where the world starts it: nothing moved.
  ros::Subscriber state_subscriber = node.subscribe<asr_msgs::RobotState>(
      "robot_state", 1, [&](const asr_msgs::RobotStateConstPtr& message) { start = *message; });
  ASSERT_TRUE(waitFor([&] { return start.has_value(); }, kHangGuardSeconds));
  const auto catalogue =
      asr_robot_model::loadObjectCatalogue(asr_robot_model::defaultObjectCatalogue());
  const asr_robot_model::World world =
      asr_robot_model::loadWorld(privateParameter("world"), catalogue);
  EXPECT_DOUBLE_EQ(start->x, world.robot.x);
  EXPECT_DOUBLE_EQ(start->y, world.robot.y);
  EXPECT_DOUBLE_EQ(start->yaw, world.robot.yaw);
}

}  // namespace
}  // namespace asr_state_machine

int main(int argc, char** argv) {
  return asr_common::testing::runRostests(argc, argv, "search_rostest");
}
