// The predictor node's messages without a master: pose clouds per instance and their markers.

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "asr_pose_prediction/ros/pose_cloud_message.hpp"
#include "asr_pose_prediction/ros/prediction_markers.hpp"

namespace asr_pose_prediction::ros_interface {
namespace {

Pose at(double x) {
  return Pose(Eigen::Vector3d(x, 0, 0), Eigen::Quaterniond::Identity());
}

SceneInstance instance(double confidence, double x) {
  SceneInstance result;
  result.scene = "gedeck";
  result.confidence = confidence;
  result.pose = at(x);
  return result;
}

// Cup: 2 poses from the best instance, 1 from the second; Plate: only from the second.
std::vector<ObjectPrediction> predictions() {
  ObjectPrediction cup;
  cup.object = {"Cup", "0"};
  cup.path = {"gedeck", "gedeck_sub0"};
  cup.poses = {at(1), at(2), at(3)};
  cup.poses_per_instance = {2, 1};
  ObjectPrediction plate;
  plate.object = {"Plate", ""};
  plate.path = {"gedeck"};
  plate.poses = {at(4)};
  plate.poses_per_instance = {0, 1};
  return {cup, plate};
}

TEST(PoseCloudMessages, OneCloudPerInstanceWithItsOwnPoses) {
  std_msgs::Header header;
  header.frame_id = "map";
  const auto clouds =
      toPoseCloudMessages(predictions(), {instance(0.9, 10), instance(0.5, 20)}, header);
  ASSERT_EQ(clouds.size(), 2u);
  EXPECT_EQ(clouds[0].header.frame_id, "map");
  EXPECT_EQ(clouds[0].scene, "gedeck");
  EXPECT_DOUBLE_EQ(clouds[0].instance_confidence, 0.9);
  EXPECT_DOUBLE_EQ(clouds[0].instance_pose.position.x, 10.0);
  ASSERT_EQ(clouds[0].objects.size(), 1u);
  EXPECT_EQ(clouds[0].objects[0].type, "Cup");
  EXPECT_EQ(clouds[0].objects[0].instance_id, "0");
  EXPECT_EQ(clouds[0].objects[0].path, (std::vector<std::string>{"gedeck", "gedeck_sub0"}));
  ASSERT_EQ(clouds[0].objects[0].poses.size(), 2u);
  EXPECT_DOUBLE_EQ(clouds[0].objects[0].poses[1].position.x, 2.0);

  ASSERT_EQ(clouds[1].objects.size(), 2u);
  EXPECT_DOUBLE_EQ(clouds[1].objects[0].poses.at(0).position.x, 3.0);
  EXPECT_EQ(clouds[1].objects[1].type, "Plate");
  EXPECT_DOUBLE_EQ(clouds[1].objects[1].poses.at(0).position.x, 4.0);
}

TEST(PoseCloudMessages, AnInstanceWithoutPosesHasNoCloud) {
  auto only_second = predictions();
  only_second.erase(only_second.begin());
  const auto clouds = toPoseCloudMessages(only_second, {instance(0.9, 10), instance(0.5, 20)}, {});
  ASSERT_EQ(clouds.size(), 1u);
  EXPECT_DOUBLE_EQ(clouds[0].instance_confidence, 0.5);
}

TEST(PredictionMarkers, ClearFirstThenAnArrowPerPoseAndALabelPerObject) {
  std_msgs::Header header;
  header.frame_id = "map";
  const auto clouds =
      toPoseCloudMessages(predictions(), {instance(0.9, 10), instance(0.5, 20)}, header);
  const visualization_msgs::MarkerArray markers = predictionMarkers(clouds, {});
  ASSERT_FALSE(markers.markers.empty());
  EXPECT_EQ(markers.markers[0].action, visualization_msgs::Marker::DELETEALL);
  std::size_t arrows = 0, labels = 0;
  std::set<std::pair<std::string, int>> ids;
  for (std::size_t i = 1; i < markers.markers.size(); ++i) {
    const auto& marker = markers.markers[i];
    EXPECT_EQ(marker.header.frame_id, "map");
    EXPECT_EQ(marker.ns.rfind("gedeck/", 0), 0u) << marker.ns;
    arrows += marker.type == visualization_msgs::Marker::ARROW;
    labels += marker.type == visualization_msgs::Marker::TEXT_VIEW_FACING;
    // Markers of one namespace must not share an id, or rviz shows only the last.
    EXPECT_TRUE(ids.insert({marker.ns, marker.id}).second) << marker.ns << " " << marker.id;
  }
  EXPECT_EQ(arrows, 4u);
  EXPECT_EQ(labels, 3u);
}

TEST(PredictionMarkers, NoCloudsOnlyClears) {
  const auto markers = predictionMarkers({}, {});
  ASSERT_EQ(markers.markers.size(), 1u);
  EXPECT_EQ(markers.markers[0].action, visualization_msgs::Marker::DELETEALL);
}

TEST(PredictionMarkers, ATypeKeepsItsColourAndTypesDiffer) {
  const auto cup = objectTypeColor("Cup", 1.0);
  const auto again = objectTypeColor("Cup", 1.0);
  const auto plate = objectTypeColor("Plate", 1.0);
  EXPECT_EQ(cup.r, again.r);
  EXPECT_EQ(cup.g, again.g);
  EXPECT_EQ(cup.b, again.b);
  EXPECT_TRUE(cup.r != plate.r || cup.g != plate.g || cup.b != plate.b);
  for (float channel : {cup.r, cup.g, cup.b}) {
    EXPECT_GE(channel, 0.0f);
    EXPECT_LE(channel, 1.0f);
  }
}

}  // namespace
}  // namespace asr_pose_prediction::ros_interface
