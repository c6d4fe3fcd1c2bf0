#include "asr_pose_prediction/ros/pose_cloud_message.hpp"

#include "asr_common/ros/object_estimate_message.hpp"

namespace asr_pose_prediction::ros_interface {

std::vector<asr_msgs::PredictedPoseCloud> toPoseCloudMessages(
    const std::vector<ObjectPrediction>& predictions, const std::vector<SceneInstance>& instances,
    const std_msgs::Header& header) {
  using asr_common::ros_interface::toPoseMessage;
  std::vector<asr_msgs::PredictedPoseCloud> clouds;
  for (std::size_t rank = 0; rank < instances.size(); ++rank) {
    asr_msgs::PredictedPoseCloud cloud;
    cloud.header = header;
    cloud.scene = instances[rank].scene;
    cloud.instance_confidence = instances[rank].confidence;
    cloud.instance_pose = toPoseMessage(instances[rank].pose);
    for (const ObjectPrediction& prediction : predictions) {
      // poses are grouped by instance, best first: skip the groups of better instances.
      std::size_t first = 0;
      for (std::size_t better = 0; better < rank && better < prediction.poses_per_instance.size();
           ++better)
        first += prediction.poses_per_instance[better];
      const std::size_t count =
          rank < prediction.poses_per_instance.size() ? prediction.poses_per_instance[rank] : 0;
      if (count == 0)
        continue;
      asr_msgs::PredictedObjectPoses& object = cloud.objects.emplace_back();
      object.type = prediction.object.type;
      object.instance_id = prediction.object.id;
      object.path = prediction.path;
      object.poses.reserve(count);
      for (std::size_t i = first; i < first + count; ++i)
        object.poses.push_back(toPoseMessage(prediction.poses[i]));
    }
    if (!cloud.objects.empty())
      clouds.push_back(std::move(cloud));
  }
  return clouds;
}

}  // namespace asr_pose_prediction::ros_interface
