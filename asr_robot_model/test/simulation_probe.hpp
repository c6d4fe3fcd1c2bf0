// Test support for the simulation's rostests: the latest /clock and robot_state, and the shipped
// kitchen as the nodes of robot_sim.launch load it.
#pragma once

#include <asr_msgs/RobotState.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>

#include <memory>

#include "asr_common/testing/rostest_support.hpp"
#include "asr_robot_model/robot_description.hpp"
#include "asr_robot_model/ros/robot_state_message.hpp"
#include "asr_robot_model/shipped_files.hpp"
#include "asr_robot_model/world.hpp"
#include "asr_robot_model/world_map.hpp"

namespace asr_robot_model::testing {

class SimulationProbe {
 public:
  SimulationProbe() {
    clock_ = handle_.subscribe<rosgraph_msgs::Clock>(
        "/clock", 10, [this](const rosgraph_msgs::ClockConstPtr& m) { latest_clock_ = m->clock; });
    state_ = handle_.subscribe<asr_msgs::RobotState>(
        "robot_state", 10, [this](const asr_msgs::RobotStateConstPtr& m) {
          latest_state_ = ros_interface::fromStateMessage(*m);
          has_state_ = true;
        });
  }

  /// Waits (wall time) until the driver's clock and state have arrived.
  bool waitForDriver(double seconds) {
    return asr_common::testing::waitFor([&] { return has_state_ && !latest_clock_.isZero(); },
                                        seconds);
  }
  /// Waits until the clock shows at least `time` (less 1 us); returns the clock then.
  ros::Time waitForClock(const ros::Time& time) {
    asr_common::testing::waitFor([&] { return (latest_clock_ - time).toSec() >= -1e-6; }, 30.0);
    return latest_clock_;
  }
  ros::Time clock() const { return latest_clock_; }
  const RobotState& state() const { return latest_state_; }

 private:
  ros::NodeHandle handle_;
  ros::Subscriber clock_, state_;
  ros::Time latest_clock_;
  RobotState latest_state_;
  bool has_state_ = false;
};

/// The shipped robot and kitchen with the nodes' default map resolution (0.02 m).
struct Kitchen {
  RobotDescription robot = loadRobotDescription(defaultRobotUrdf());
  World world = loadWorld(shippedFile("config/worlds/kitchen.yaml"),
                          loadObjectCatalogue(defaultObjectCatalogue()));
  WorldMap map{world, 0.02, robot.base_radius};
};

}  // namespace asr_robot_model::testing
