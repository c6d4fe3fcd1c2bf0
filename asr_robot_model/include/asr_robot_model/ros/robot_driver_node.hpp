#pragma once

#include <actionlib/server/simple_action_server.h>
#include <asr_msgs/AdvanceClock.h>
#include <asr_msgs/MoveHeadAction.h>
#include <asr_msgs/MoveRobotAction.h>
#include <ros/ros.h>
#include <tf2_msgs/TFMessage.h>
#include <tf2_ros/static_transform_broadcaster.h>

#include <functional>
#include <mutex>

#include "asr_robot_model/goal_check.hpp"
#include "asr_robot_model/motion_model.hpp"
#include "asr_robot_model/ros/simulated_clock.hpp"
#include "asr_robot_model/ros/simulation_setup.hpp"

// robot_driver in simulation: the one interface the search uses for the robot (docs/robot.md).
// Actions move_robot (base and head) and move_head; the robot moves along the motion model, one
// motion at a time, publishing joint_states, robot_state and tf (map -> base_footprint and the
// URDF's frames) every ~time_step simulated seconds; service advance_clock lets simulated time
// pass without motion. Goals are checked before the robot moves and refused with the reason.
namespace asr_robot_model::ros_interface {

class RobotDriverNode {
 public:
  /// Reads and checks the parameters (SimulationSetup's and ~base_speed, ~turn_speed,
  /// ~pan_speed, ~tilt_speed, ~time_step, ~real_time_factor, ~clock_start, ~fixed_frame);
  /// throws asr_common::InputError naming a bad one or a start state the world refuses.
  RobotDriverNode(ros::NodeHandle node, ros::NodeHandle private_node);

 private:
  void moveRobot(const asr_msgs::MoveRobotGoalConstPtr& goal);
  void moveHead(const asr_msgs::MoveHeadGoalConstPtr& goal);
  /// Refuses the goal with `verdict`'s reason, or moves to `target` and reports the result of
  /// action `action` on `server`.
  template <typename Result, typename Feedback, typename Server>
  void runMotion(Server& server, const char* action, const GoalVerdict& verdict,
                 const RobotState& target);
  bool advanceClock(asr_msgs::AdvanceClock::Request& request,
                    asr_msgs::AdvanceClock::Response& response);

  /// Moves to `target` along the motion model, calling `feedback(elapsed, remaining)` after
  /// every step; false if `preempted()` said so (the robot stops where it is). `seconds`: the
  /// time the motion took.
  bool execute(const RobotState& target, const std::function<bool()>& preempted,
               const std::function<void(double, double)>& feedback, double& seconds);
  /// Sets the robot's state and publishes it (joint_states, robot_state, tf).
  void publishState(const RobotState& state);
  /// The moving frames (map -> base_footprint and the moving joints) now.
  tf2_msgs::TFMessage movingFrames() const;
  /// A new /tf subscriber (rviz, a listener started late) gets the current frames at once: the
  /// simulated clock may stand still for long, and then nothing else is published.
  void greetFrameSubscriber(const ros::SingleSubscriberPublisher& subscriber);

  ros::NodeHandle node_;
  SimulationSetup setup_;
  MotionSpeeds speeds_;
  double time_step_;
  std::string fixed_frame_;
  SimulatedClock clock_;
  std::mutex motion_mutex_;         // one motion or clock advance at a time
  mutable std::mutex state_mutex_;  // state_ and what is published of it
  RobotState state_;
  ros::Publisher joint_states_;
  ros::Publisher robot_state_;
  ros::Publisher frames_;
  tf2_ros::StaticTransformBroadcaster fixed_frames_;
  ros::ServiceServer advance_clock_;
  actionlib::SimpleActionServer<asr_msgs::MoveRobotAction> move_robot_;
  actionlib::SimpleActionServer<asr_msgs::MoveHeadAction> move_head_;
};

}  // namespace asr_robot_model::ros_interface
