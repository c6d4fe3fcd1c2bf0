#include "asr_robot_model/ros/simulated_clock.hpp"

#include <rosgraph_msgs/Clock.h>

namespace asr_robot_model::ros_interface {

SimulatedClock::SimulatedClock(ros::NodeHandle& node, bool owns_time, double real_time_factor,
                               ros::Time start)
    : owns_time_(owns_time), real_time_factor_(real_time_factor), now_(start) {
  if (!owns_time_)
    return;
  clock_ = node.advertise<rosgraph_msgs::Clock>("/clock", 1, true);
  rosgraph_msgs::Clock message;
  message.clock = now_;
  clock_.publish(message);
}

ros::Time SimulatedClock::now() const {
  return owns_time_ ? now_ : ros::Time::now();
}

void SimulatedClock::advanceTo(const ros::Time& time) {
  if (!owns_time_) {
    const ros::Duration left = time - ros::Time::now();
    if (left > ros::Duration(0))
      left.sleep();
    return;
  }
  if (time <= now_)
    return;
  if (real_time_factor_ > 0.0)
    ros::WallDuration((time - now_).toSec() / real_time_factor_).sleep();
  now_ = time;
  rosgraph_msgs::Clock message;
  message.clock = now_;
  clock_.publish(message);
}

bool useSimTime() {
  bool use = false;
  ros::param::get("/use_sim_time", use);
  return use;
}

}  // namespace asr_robot_model::ros_interface
