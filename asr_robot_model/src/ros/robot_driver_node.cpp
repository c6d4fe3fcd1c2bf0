#include "asr_robot_model/ros/robot_driver_node.hpp"

#include <geometry_msgs/TransformStamped.h>
#include <sensor_msgs/JointState.h>
#include <tf2_eigen/tf2_eigen.h>

#include "asr_common/input_error.hpp"
#include "asr_common/ros/node_parameters.hpp"
#include "asr_common/ros/queue_sizes.hpp"
#include "asr_robot_model/forward_kinematics.hpp"
#include "asr_robot_model/robot_frames.hpp"
#include "asr_robot_model/ros/robot_state_message.hpp"

namespace asr_robot_model::ros_interface {
namespace {

using namespace asr_common::ros_interface;

MotionSpeeds speedParameters(const ros::NodeHandle& node, const RobotDescription& robot) {
  const MotionSpeeds defaults = speedsOf(robot);
  MotionSpeeds speeds;
  speeds.base_speed = numberParameter(node, "base_speed", defaults.base_speed, 1e-3, 100.0);
  speeds.turn_speed = numberParameter(node, "turn_speed", defaults.turn_speed, 1e-3, 100.0);
  speeds.pan_speed = numberParameter(node, "pan_speed", defaults.pan_speed, 1e-3, 100.0);
  speeds.tilt_speed = numberParameter(node, "tilt_speed", defaults.tilt_speed, 1e-3, 100.0);
  return speeds;
}

geometry_msgs::TransformStamped transformMessage(const FrameTransform& frame,
                                                 const ros::Time& stamp) {
  geometry_msgs::TransformStamped message = tf2::eigenToTransform(frame.transform);
  message.header.stamp = stamp;
  message.header.frame_id = frame.parent;
  message.child_frame_id = frame.child;
  return message;
}

template <typename Result>
Result resultOf(const GoalVerdict& verdict, const RobotState& state) {
  Result result;
  result.outcome = static_cast<std::uint8_t>(verdict.refusal);
  result.message = verdict.message;
  result.state = toStateMessage(state);
  return result;
}

}  // namespace

RobotDriverNode::RobotDriverNode(ros::NodeHandle node, ros::NodeHandle private_node)
    : node_(node),
      setup_(loadSimulationSetup(private_node)),
      speeds_(speedParameters(private_node, setup_.robot)),
      time_step_(numberParameter(private_node, "time_step", 0.1, 1e-3, 10.0)),
      fixed_frame_(fixedFrameParameter(private_node)),
      clock_(node_, useSimTime(), numberParameter(private_node, "real_time_factor", 0.0, 0.0, 1e6),
             ros::Time(numberParameter(private_node, "clock_start", 1.0, 1e-3, 1e9))),
      state_(setup_.world.robot),
      move_robot_(
          node_, "move_robot", [this](const auto& goal) { moveRobot(goal); }, false),
      move_head_(
          node_, "move_head", [this](const auto& goal) { moveHead(goal); }, false) {
  const GoalVerdict start = checkStateGoal(setup_.robot, setup_.world, *setup_.map, state_);
  if (start.refusal != GoalRefusal::kNone)
    throw asr_common::InputError("the world's robot start state is refused: " + start.message);
  joint_states_ = node_.advertise<sensor_msgs::JointState>("joint_states", kResultQueue);
  robot_state_ = node_.advertise<asr_msgs::RobotState>("robot_state", kLatchedQueue, true);
  frames_ = node_.advertise<tf2_msgs::TFMessage>(
      "/tf", kResultQueue, [this](const ros::SingleSubscriberPublisher& subscriber) {
        greetFrameSubscriber(subscriber);
      });
  std::vector<geometry_msgs::TransformStamped> fixed;
  for (const FrameTransform& frame : fixedFrames(setup_.robot))
    fixed.push_back(transformMessage(frame, clock_.now()));
  fixed_frames_.sendTransform(fixed);
  publishState(state_);
  advance_clock_ = node_.advertiseService("advance_clock", &RobotDriverNode::advanceClock, this);
  move_robot_.start();
  move_head_.start();
}

void RobotDriverNode::moveRobot(const asr_msgs::MoveRobotGoalConstPtr& goal) {
  std::lock_guard<std::mutex> lock(motion_mutex_);
  const RobotState target = fromStateMessage(goal->target);
  runMotion<asr_msgs::MoveRobotResult, asr_msgs::MoveRobotFeedback>(
      move_robot_, "move_robot", checkStateGoal(setup_.robot, setup_.world, *setup_.map, target),
      target);
}

void RobotDriverNode::moveHead(const asr_msgs::MoveHeadGoalConstPtr& goal) {
  std::lock_guard<std::mutex> lock(motion_mutex_);
  RobotState target = state_;
  target.pan = goal->pan;
  target.tilt = goal->tilt;
  runMotion<asr_msgs::MoveHeadResult, asr_msgs::MoveHeadFeedback>(
      move_head_, "move_head", checkHeadGoal(setup_.robot, goal->pan, goal->tilt), target);
}

template <typename Result, typename Feedback, typename Server>
void RobotDriverNode::runMotion(Server& server, const char* action, const GoalVerdict& verdict,
                                const RobotState& target) {
  if (verdict.refusal != GoalRefusal::kNone) {
    ROS_WARN("robot_driver: %s goal refused: %s", action, verdict.message.c_str());
    server.setAborted(resultOf<Result>(verdict, state_), verdict.message);
    return;
  }
  double seconds = 0.0;
  const bool reached = execute(
      target, [&server] { return server.isPreemptRequested(); },
      [this, &server](double elapsed, double remaining) {
        Feedback feedback;
        feedback.state = toStateMessage(state_);
        feedback.seconds_elapsed = elapsed;
        feedback.seconds_remaining = remaining;
        server.publishFeedback(feedback);
      },
      seconds);
  Result result = resultOf<Result>({}, state_);
  result.seconds = seconds;
  if (reached) {
    server.setSucceeded(result);
    return;
  }
  result.outcome = Result::PREEMPTED;
  result.message = "preempted";
  server.setPreempted(result, result.message);
}

bool RobotDriverNode::execute(const RobotState& target, const std::function<bool()>& preempted,
                              const std::function<void(double, double)>& feedback,
                              double& seconds) {
  const RobotState start = state_;
  const double total = motionBetween(start, target, speeds_).seconds;
  const ros::Time start_time = clock_.now();
  double elapsed = 0.0;
  while (elapsed < total) {
    if (preempted() || !ros::ok()) {
      seconds = elapsed;
      return false;
    }
    // The last step lands exactly on the motion's end, so the clock advances by `total`.
    elapsed = total - elapsed <= time_step_ ? total : elapsed + time_step_;
    clock_.advanceTo(start_time + ros::Duration(elapsed));
    publishState(stateAlong(start, target, speeds_, elapsed));
    feedback(elapsed, total - elapsed);
  }
  publishState(target);
  seconds = total;
  return true;
}

bool RobotDriverNode::advanceClock(asr_msgs::AdvanceClock::Request& request,
                                   asr_msgs::AdvanceClock::Response& response) {
  if (!(std::isfinite(request.seconds) && request.seconds >= 0.0)) {
    ROS_WARN("robot_driver: advance_clock refused: seconds = %g must be finite and >= 0",
             request.seconds);
    return false;
  }
  std::lock_guard<std::mutex> lock(motion_mutex_);
  clock_.advanceTo(clock_.now() + ros::Duration(request.seconds));
  publishState(state_);
  response.now = clock_.now();
  response.state = toStateMessage(state_);
  return true;
}

tf2_msgs::TFMessage RobotDriverNode::movingFrames() const {
  const ros::Time stamp = clock_.now();
  tf2_msgs::TFMessage frames;
  frames.transforms.push_back(
      transformMessage({fixed_frame_, kBaseFrame, baseInMap(state_)}, stamp));
  for (const FrameTransform& frame :
       asr_robot_model::movingFrames(setup_.robot, state_.pan, state_.tilt))
    frames.transforms.push_back(transformMessage(frame, stamp));
  return frames;
}

void RobotDriverNode::greetFrameSubscriber(const ros::SingleSubscriberPublisher& subscriber) {
  std::lock_guard<std::mutex> lock(state_mutex_);
  subscriber.publish(movingFrames());
}

void RobotDriverNode::publishState(const RobotState& state) {
  std::lock_guard<std::mutex> lock(state_mutex_);
  state_ = state;
  const ros::Time stamp = clock_.now();
  sensor_msgs::JointState joints;
  joints.header.stamp = stamp;
  joints.name = {setup_.robot.pan.name, setup_.robot.tilt.name};
  joints.position = {state_.pan, state_.tilt};
  joint_states_.publish(joints);
  robot_state_.publish(toStateMessage(state_));
  frames_.publish(movingFrames());
}

}  // namespace asr_robot_model::ros_interface
