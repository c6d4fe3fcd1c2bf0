#include "asr_robot_model/goal_check.hpp"

#include <cmath>
#include <sstream>

namespace asr_robot_model {
namespace {

GoalVerdict refuse(GoalRefusal refusal, const std::string& message) {
  return {refusal, message};
}

std::string describe(const std::string& field, double value) {
  std::ostringstream text;
  text << field << " = " << value;
  return text.str();
}

GoalVerdict checkJoint(const RevoluteJoint& joint, const std::string& field, double angle) {
  if (!std::isfinite(angle))
    return refuse(GoalRefusal::kInvalid, describe(field, angle) + " is not a finite number");
  if (!joint.withinLimits(angle)) {
    std::ostringstream text;
    text << describe(field, angle) << " is outside the limits [" << joint.lower << ", "
         << joint.upper << "] of " << joint.name;
    return refuse(GoalRefusal::kJointLimit, text.str());
  }
  return {};
}

// The furniture whose footprint, grown by the base radius, holds (x, y); empty if none does.
std::string furnitureAt(const World& world, double x, double y, double base_radius) {
  for (const Furniture& piece : world.furniture) {
    const Eigen::Vector3d point(x, y, piece.box.pose.position.z());
    if (piece.box.contains(point, base_radius))
      return piece.name;
  }
  return "";
}

}  // namespace

GoalVerdict checkHeadGoal(const RobotDescription& robot, double pan, double tilt) {
  GoalVerdict verdict = checkJoint(robot.pan, "pan", pan);
  return verdict.refusal != GoalRefusal::kNone ? verdict : checkJoint(robot.tilt, "tilt", tilt);
}

GoalVerdict checkStateGoal(const RobotDescription& robot, const World& world, const WorldMap& map,
                           const RobotState& goal) {
  for (const auto& [field, value] : {std::pair{"x", goal.x}, {"y", goal.y}, {"yaw", goal.yaw}}) {
    if (!std::isfinite(value))
      return refuse(GoalRefusal::kInvalid, describe(field, value) + " is not a finite number");
  }
  const GoalVerdict head = checkHeadGoal(robot, goal.pan, goal.tilt);
  if (head.refusal != GoalRefusal::kNone)
    return head;
  std::ostringstream where;
  where << "the base at (" << goal.x << ", " << goal.y << ") with radius " << robot.base_radius;
  const double r = robot.base_radius;
  if (goal.x - r < world.room_min.x() || goal.x + r > world.room_max.x() ||
      goal.y - r < world.room_min.y() || goal.y + r > world.room_max.y())
    return refuse(GoalRefusal::kOutsideRoom, where.str() + " would leave the room");
  if (!map.baseIsFree(goal.x, goal.y)) {
    const std::string name = furnitureAt(world, goal.x, goal.y, r);
    return refuse(GoalRefusal::kBaseCollision,
                  where.str() + " would meet " +
                      (name.empty() ? std::string("furniture") : "furniture '" + name + "'"));
  }
  return {};
}

}  // namespace asr_robot_model
