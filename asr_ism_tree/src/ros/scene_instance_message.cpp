#include "asr_ism_tree/ros/scene_instance_message.hpp"

#include <cmath>

#include "asr_common/input_error.hpp"
#include "asr_common/ros/object_estimate_message.hpp"

namespace asr_ism_tree::ros_interface {

using asr_common::ros_interface::fromPoseMessage;
using asr_common::ros_interface::toPoseMessage;

asr_msgs::SceneInstance toSceneInstanceMessage(const SceneInstance& instance,
                                               const std_msgs::Header& header) {
  asr_msgs::SceneInstance message;
  message.header = header;
  message.scene = instance.scene;
  message.confidence = instance.confidence;
  message.object_confidence = instance.object_confidence;
  message.ids_ignored = instance.ids_ignored;
  message.search_complete = instance.search_complete;
  message.pose = toPoseMessage(instance.pose);
  for (const InstanceObject& object : instance.objects) {
    asr_msgs::ObjectRating& rating = message.objects.emplace_back();
    rating.type = object.key.type;
    rating.instance_id = object.key.id;
    rating.pose = toPoseMessage(object.pose);
    rating.similarity = object.similarity;
    rating.position_compliance = object.position_compliance;
    rating.orientation_compliance = object.orientation_compliance;
  }
  for (const ObjectKey& key : instance.missing) {
    asr_msgs::ObjectKey& missing = message.missing.emplace_back();
    missing.type = key.type;
    missing.instance_id = key.id;
  }
  for (const InstanceIsm& ism : instance.isms) {
    asr_msgs::IsmRating& rating = message.isms.emplace_back();
    rating.name = ism.name;
    rating.recognized = ism.recognized;
    rating.objective = ism.objective;
    rating.reference_pose = toPoseMessage(ism.recognized ? ism.reference_pose : Pose());
  }
  return message;
}

SceneInstance fromSceneInstanceMessage(const asr_msgs::SceneInstance& message) {
  const std::string what = "scene instance of '" + message.scene + "'";
  if (message.scene.empty())
    throw asr_common::InputError("a scene instance without a scene name");
  if (!(message.confidence >= 0.0 && message.confidence <= 1.0))
    throw asr_common::InputError(what + ": confidence " + std::to_string(message.confidence) +
                                 " is not in [0, 1]");
  if (!(message.object_confidence >= 0.0 && message.object_confidence <= 1.0))
    throw asr_common::InputError(what + ": object confidence " +
                                 std::to_string(message.object_confidence) + " is not in [0, 1]");
  SceneInstance instance;
  instance.scene = message.scene;
  instance.confidence = message.confidence;
  instance.object_confidence = message.object_confidence;
  instance.ids_ignored = message.ids_ignored;
  instance.search_complete = message.search_complete;
  instance.pose = fromPoseMessage(message.pose, what);
  for (const asr_msgs::ObjectRating& rating : message.objects) {
    InstanceObject& object = instance.objects.emplace_back();
    object.key = {rating.type, rating.instance_id};
    object.pose = fromPoseMessage(rating.pose, what + ", object " + object.key.toString());
    object.similarity = std::isfinite(rating.similarity) ? rating.similarity : 0.0;
    object.position_compliance = rating.position_compliance;
    object.orientation_compliance = rating.orientation_compliance;
  }
  for (const asr_msgs::ObjectKey& key : message.missing)
    instance.missing.push_back({key.type, key.instance_id});
  for (const asr_msgs::IsmRating& rating : message.isms) {
    InstanceIsm& ism = instance.isms.emplace_back();
    ism.name = rating.name;
    ism.recognized = rating.recognized;
    ism.objective = rating.objective;
    if (rating.recognized)
      ism.reference_pose = fromPoseMessage(rating.reference_pose, what + ", ISM " + rating.name);
  }
  return instance;
}

}  // namespace asr_ism_tree::ros_interface
