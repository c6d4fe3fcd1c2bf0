#pragma once

#include <ros/ros.h>

// The time of the robot's simulation. With /use_sim_time the simulation owns time: it publishes
// /clock (latched, so late subscribers learn the time) and advances it by the simulated
// durations only, as fast as possible (real_time_factor 0) or at real_time_factor times wall
// time; between motions the clock stands still. Without /use_sim_time it follows wall time and
// waiting is sleeping.
namespace asr_robot_model::ros_interface {

class SimulatedClock {
 public:
  /// `start`: the first simulated time (roscpp takes time zero for "no clock yet").
  SimulatedClock(ros::NodeHandle& node, bool owns_time, double real_time_factor, ros::Time start);

  bool ownsTime() const { return owns_time_; }
  ros::Time now() const;
  /// Lets time pass until `time` (no-op if it has come): publishes it on /clock, or sleeps.
  void advanceTo(const ros::Time& time);

 private:
  bool owns_time_;
  double real_time_factor_;
  ros::Time now_;
  ros::Publisher clock_;
};

/// Whether the node runs on simulated time (the /use_sim_time parameter).
bool useSimTime();

}  // namespace asr_robot_model::ros_interface
