// What the system tests share: the kitchen's models learned once per test binary, and
// asr_state_machine's search.launch started as a user starts it, watched through the
// executive's latched ~state and ~result.
#pragma once

#include <ros/ros.h>
#include <std_msgs/String.h>

#include <algorithm>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "asr_common/child_process.hpp"

namespace asr_integration_tests {

/// A wall-clock guard against a hang, far beyond what a search needs on a loaded 2-core machine:
/// the searches run on simulated time, as fast as the nodes compute.
constexpr double kHangGuardSeconds = 600.0;

/// The kitchen's scene models learned from the recordings (once per process) into a temporary
/// folder; its path.
std::string kitchenModels();

/// A file of this folder (ASR_INTEGRATION_TESTS_DIR), or of asr_state_machine's config.
std::string testFile(const std::string& name);
std::string kitchenWorld();

/// `roslaunch asr_state_machine search.launch ARGS...` on the test's master (rviz off), and the
/// executive's latched ~state and ~result. Stopped like Ctrl-C when it goes.
class SearchLaunch {
 public:
  SearchLaunch(const std::string& name, const std::vector<std::string>& arguments);
  ~SearchLaunch();
  SearchLaunch(const SearchLaunch&) = delete;
  SearchLaunch& operator=(const SearchLaunch&) = delete;

  /// Spins until the executive has published the state `state` (now or earlier; true) or the
  /// guard ran out.
  bool waitForState(const std::string& state, double guard_seconds = kHangGuardSeconds);
  /// Spins until the result comes; the result (what `asr search --json` prints), or nullopt if
  /// the guard ran out.
  std::optional<nlohmann::json> waitForResult(double guard_seconds = kHangGuardSeconds);
  std::string lastState() const { return state_.value_or("(none)"); }
  /// The end of roslaunch's output, for failure messages.
  std::string logTail() const;

 private:
  std::string log_;
  std::unique_ptr<asr_common::ChildProcess> launch_;
  ros::NodeHandle node_;
  ros::Subscriber result_subscriber_, state_subscriber_;
  std::optional<std::string> result_, state_;
  std::vector<std::string> states_;  // every state published, in order
};

/// The process id of a running node, asked of the node itself through the master (its
/// XML-RPC getPid); nullopt if the master does not know it.
std::optional<int> nodePid(const std::string& node);

}  // namespace asr_integration_tests
