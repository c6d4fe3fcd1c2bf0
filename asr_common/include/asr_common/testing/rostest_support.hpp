// Test support for the suite's rostests: waiting on ROS without fixed sleeps, and main().
#pragma once

#include <gtest/gtest.h>
#include <ros/ros.h>

#include <string>

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

/// The main() of a rostest's gtest node: gtest, ros::init, a node handle that keeps the
/// connection to the master for the whole run.
inline int runRostests(int argc, char** argv, const std::string& name) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, name);
  ros::NodeHandle keep_alive;
  return RUN_ALL_TESTS();
}

}  // namespace asr_common::testing
