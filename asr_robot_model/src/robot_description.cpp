#include "asr_robot_model/robot_description.hpp"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <vector>

#include "asr_common/input_error.hpp"
#include "asr_robot_model/shipped_files.hpp"

namespace asr_robot_model {
namespace {

using asr_common::InputError;

Eigen::Isometry3d toIsometry(const urdf::Pose& pose) {
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
  transform.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  transform.linear() =
      Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z)
          .normalized()
          .toRotationMatrix();
  return transform;
}

[[noreturn]] void fail(const std::string& source, const std::string& field,
                       const std::string& problem) {
  throw InputError(source + ": " + field + ": " + problem);
}

RevoluteJoint revoluteJoint(const urdf::Joint& joint, const std::string& source) {
  const std::string field = "joint '" + joint.name + "'";
  if (joint.type != urdf::Joint::REVOLUTE)
    fail(source, field, "must be revolute (with limits)");
  if (!joint.limits)
    fail(source, field + " limit", "missing");
  RevoluteJoint result;
  result.name = joint.name;
  result.axis = Eigen::Vector3d(joint.axis.x, joint.axis.y, joint.axis.z);
  if (!result.axis.allFinite() || result.axis.norm() < 1e-9)
    fail(source, field + " axis", "not a direction");
  result.axis.normalize();
  result.lower = joint.limits->lower;
  result.upper = joint.limits->upper;
  result.velocity = joint.limits->velocity;
  if (!(std::isfinite(result.lower) && std::isfinite(result.upper) && result.lower < result.upper))
    fail(source, field + " limit", "lower must be below upper");
  if (!(result.lower >= -M_PI && result.upper <= M_PI))
    fail(source, field + " limit", "must lie within -pi..pi");
  if (!(std::isfinite(result.velocity) && result.velocity > 0.0))
    fail(source, field + " limit velocity", "must be positive");
  return result;
}

// The joints from base_footprint down to camera_optical_frame, root first.
std::vector<urdf::JointConstSharedPtr> chainToCamera(const urdf::ModelInterface& model,
                                                     const std::string& source) {
  if (!model.getLink(kBaseFrame))
    fail(source, std::string("link '") + kBaseFrame + "'", "missing");
  urdf::LinkConstSharedPtr link = model.getLink(kCameraFrame);
  if (!link)
    fail(source, std::string("link '") + kCameraFrame + "'", "missing");
  std::vector<urdf::JointConstSharedPtr> chain;
  while (link->name != kBaseFrame) {
    if (!link->parent_joint)
      fail(source, std::string("link '") + kCameraFrame + "'",
           std::string("not below ") + kBaseFrame);
    chain.insert(chain.begin(), link->parent_joint);
    link = model.getLink(link->parent_joint->parent_link_name);
  }
  return chain;
}

double cylinderRadius(const urdf::ModelInterface& model, const std::string& source) {
  const urdf::LinkConstSharedPtr base = model.getLink(kBaseLink);
  const std::string field = std::string("link '") + kBaseLink + "' collision";
  if (!base || !base->collision || !base->collision->geometry ||
      base->collision->geometry->type != urdf::Geometry::CYLINDER)
    fail(source, field, "needs a cylinder (the base footprint for free-space checks)");
  const auto& cylinder = static_cast<const urdf::Cylinder&>(*base->collision->geometry);
  if (!(cylinder.radius > 0.0))
    fail(source, field + " radius", "must be positive");
  return cylinder.radius;
}

// Collects urdfdom's messages (it reports through console_bridge, on stderr by default) while it
// parses, so that the InputError can say what was wrong and nothing else is printed.
class ParserMessages : public console_bridge::OutputHandler {
 public:
  ParserMessages() {
    previous_ = console_bridge::getOutputHandler();
    console_bridge::useOutputHandler(this);
  }
  ~ParserMessages() override { console_bridge::useOutputHandler(previous_); }
  ParserMessages(const ParserMessages&) = delete;
  ParserMessages& operator=(const ParserMessages&) = delete;

  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR && first_error_.empty())
      first_error_ = text;
  }
  const std::string& firstError() const { return first_error_; }

 private:
  console_bridge::OutputHandler* previous_ = nullptr;
  std::string first_error_;
};

std::vector<UrdfJoint> allJoints(const urdf::ModelInterface& model) {
  std::vector<UrdfJoint> joints;
  for (const auto& [name, joint] : model.joints_) {
    UrdfJoint entry;
    entry.name = name;
    entry.parent = joint->parent_link_name;
    entry.child = joint->child_link_name;
    entry.origin = toIsometry(joint->parent_to_joint_origin_transform);
    entry.moves = joint->type == urdf::Joint::REVOLUTE || joint->type == urdf::Joint::CONTINUOUS;
    const Eigen::Vector3d axis(joint->axis.x, joint->axis.y, joint->axis.z);
    if (entry.moves && axis.allFinite() && axis.norm() > 1e-9)
      entry.axis = axis.normalized();
    joints.push_back(entry);
  }
  return joints;
}

urdf::ModelInterfaceSharedPtr parsedModel(const std::string& urdf_xml, const std::string& source) {
  ParserMessages messages;
  urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(urdf_xml);
  if (!model)
    fail(source, "robot",
         "not a valid URDF: " + (messages.firstError().empty() ? "urdfdom could not parse it"
                                                               : messages.firstError()));
  return model;
}

}  // namespace

RobotDescription parseRobotDescription(const std::string& urdf_xml, const std::string& source) {
  const urdf::ModelInterfaceSharedPtr model = parsedModel(urdf_xml, source);
  RobotDescription robot;
  robot.source = source;
  // Fixed transforms accumulate into the segment before the pan joint, between the joints and
  // after the tilt joint; each revolute joint's origin ends its segment.
  Eigen::Isometry3d* segment = &robot.base_to_pan;
  int revolute_seen = 0;
  for (const urdf::JointConstSharedPtr& joint : chainToCamera(*model, source)) {
    *segment = *segment * toIsometry(joint->parent_to_joint_origin_transform);
    if (joint->type == urdf::Joint::FIXED)
      continue;
    const std::string expected = revolute_seen == 0 ? kPanJoint : kTiltJoint;
    if (joint->name != expected || revolute_seen == 2)
      fail(source, "joint '" + joint->name + "'",
           "the chain to the camera may move only at ptu_pan_joint then ptu_tilt_joint");
    if (revolute_seen == 0) {
      robot.pan = revoluteJoint(*joint, source);
      segment = &robot.pan_to_tilt;
    } else {
      robot.tilt = revoluteJoint(*joint, source);
      segment = &robot.tilt_to_camera;
    }
    ++revolute_seen;
  }
  if (revolute_seen != 2)
    fail(source, std::string("joint '") + (revolute_seen == 0 ? kPanJoint : kTiltJoint) + "'",
         "missing from the chain base_footprint -> camera_optical_frame");
  // The base turns about the vertical; a pan axis off the vertical would change the camera's
  // height and elevation with pan, which the inverse kinematics does not model.
  const Eigen::Vector3d pan_axis_in_base = robot.base_to_pan.linear() * robot.pan.axis;
  if (std::abs(std::abs(pan_axis_in_base.z()) - 1.0) > 1e-9)
    fail(source, std::string("joint '") + kPanJoint + "' axis",
         "must be vertical in base_footprint");
  robot.base_radius = cylinderRadius(*model, source);
  robot.joints = allJoints(*model);
  return robot;
}

RobotDescription loadRobotDescription(const std::string& urdf_path) {
  std::ifstream file(urdf_path);
  if (!file)
    throw InputError(urdf_path + ": cannot read the URDF file");
  const std::string xml((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  return parseRobotDescription(xml, urdf_path);
}

std::string defaultRobotUrdf() {
  return shippedFile("urdf/asr_robot.urdf");
}

}  // namespace asr_robot_model
