// Test support for the suite's rostests: waiting on ROS without fixed sleeps, and main().
#pragma once

#include <gtest/gtest.h>
#include <ros/ros.h>

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "asr_common/child_process.hpp"

namespace asr_common::testing {

/// Spins until `done()` holds or `seconds` (wall clock) have passed; returns done().
template <typename Condition>
bool waitFor(Condition done, double seconds) {
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(seconds);
  while (!done() && ros::WallTime::now() < deadline && ros::ok()) {
    ros::spinOnce();
    ros::WallDuration(0.01).sleep();
  }
  return done();
}

/// A launch file of asr_bringup started as a user starts it (`roslaunch asr_bringup FILE
/// ARGS...`), on the test's master, so the tests cover the launch files' wiring: node names,
/// parameter files, remappings. Its output goes to `log`; stopped like Ctrl-C when it goes.
class Launch {
 public:
  Launch(const std::string& file, const std::vector<std::string>& arguments,
         const std::string& log) {
    std::vector<std::string> all = {"asr_bringup", file};
    all.insert(all.end(), arguments.begin(), arguments.end());
    process_ = std::make_unique<ChildProcess>("/usr/bin/roslaunch", all, log, log);
  }
  Launch(const Launch&) = delete;
  Launch& operator=(const Launch&) = delete;
  ~Launch() { stop(); }

  ChildProcess& process() { return *process_; }
  /// Ctrl-C: roslaunch stops its nodes (each gets SIGINT) and ends.
  void stop() { process_->stop(std::chrono::seconds(30)); }

 private:
  std::unique_ptr<ChildProcess> process_;
};

/// The main() of a rostest's gtest node: gtest, ros::init, a node handle that keeps the
/// connection to the master for the whole run.
inline int runRostests(int argc, char** argv, const std::string& name) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, name);
  ros::NodeHandle keep_alive;
  return RUN_ALL_TESTS();
}

}  // namespace asr_common::testing
