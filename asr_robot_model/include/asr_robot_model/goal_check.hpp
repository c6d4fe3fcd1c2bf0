#pragma once

#include <string>

#include "asr_robot_model/robot_description.hpp"
#include "asr_robot_model/robot_state.hpp"
#include "asr_robot_model/world.hpp"
#include "asr_robot_model/world_map.hpp"

namespace asr_robot_model {

/// Why the driver refuses a goal state before moving (the values match asr_msgs' MoveRobot and
/// MoveHead results).
enum class GoalRefusal {
  kNone = 0,
  kInvalid = 1,
  kJointLimit = 2,
  kOutsideRoom = 3,
  kBaseCollision = 4
};

struct GoalVerdict {
  GoalRefusal refusal = GoalRefusal::kNone;
  std::string message;  // names the field and the value; empty when accepted
};

/// Checks the head angles of a goal: finite and within the URDF's joint limits.
GoalVerdict checkHeadGoal(const RobotDescription& robot, double pan, double tilt);

/// Checks a whole goal state: finite values, head within its limits, the base's footprint inside
/// the room and clear of furniture (the message names the furniture the base would meet).
GoalVerdict checkStateGoal(const RobotDescription& robot, const World& world, const WorldMap& map,
                           const RobotState& goal);

}  // namespace asr_robot_model
