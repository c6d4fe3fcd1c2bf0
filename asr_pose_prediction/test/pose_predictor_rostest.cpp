// The pose_predictor node end to end, with a ROS master (rostest): poses for the objects left out
// of a recorded configuration, through the service and through the scene_instances topic, and
// clear messages when there is nothing to predict from.

#include <asr_msgs/PredictPoses.h>
#include <asr_msgs/SceneInstanceList.h>
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <set>

#include "asr_common/child_process.hpp"
#include "asr_common/testing/recordings_skip.hpp"
#include "asr_common/testing/rostest_support.hpp"
#include "asr_common/testing/temp_dir.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"
#include "asr_ism_tree/ros/scene_instance_message.hpp"
#include "asr_ism_tree/sqlite/model_store.hpp"
#include "asr_ism_tree/tree_generation.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"

namespace asr_pose_prediction {
namespace {

using asr_common::testing::Launch;
using asr_common::testing::TempDir;
using asr_common::testing::waitFor;

class PosePredictorNodeTest : public ::testing::Test {
 protected:
  void SetUp() override {
    REQUIRE_RECORDINGS();
    demonstration_ = asr_ism::sqlite::readDemonstration(
        asr_common::testing::recording("story_1.sqlite"), "gedeck");
    tree_ = asr_ism_tree::generateIsmTree(
        demonstration_, asr_ism_tree::RelationTopology::complete(demonstration_.objects()), {});
    const std::string model = dir_.file("gedeck.sqlite");
    asr_ism_tree::sqlite::saveIsmTree(model, tree_, "test");
    // As a user starts it, with the shipped parameter file; the test plays the recogniser.
    launch_ = std::make_unique<Launch>("recognize.launch",
                                       std::vector<std::string>{"model_files:=[" + model + "]",
                                                                "rviz:=false", "recognizer:=false"},
                                       dir_.file("recognize_launch.log"));
    predict_ = handle_.serviceClient<asr_msgs::PredictPoses>("predict_poses");
    ASSERT_TRUE(predict_.waitForExistence(ros::Duration(30))) << "pose_predictor did not start";
  }

  // The instance of recorded set `set` without the objects of `left_out` types, as a message.
  asr_msgs::SceneInstance instanceWithout(std::size_t set, const std::set<std::string>& left_out) {
    asr_common::Configuration configuration;
    for (const auto& estimate : demonstration_.configuration(set)) {
      if (!left_out.count(estimate.key.type))
        configuration.push_back(estimate);
    }
    const auto instances = asr_ism_tree::TreeRecognizer(tree_).recognize(configuration);
    EXPECT_FALSE(instances.empty());
    std_msgs::Header header;
    header.frame_id = "map";
    return asr_ism_tree::ros_interface::toSceneInstanceMessage(instances.at(0), header);
  }

  TempDir dir_{"asr_pose_predictor_rostest"};
  asr_ism::Demonstration demonstration_;
  asr_ism_tree::IsmTree tree_;
  std::unique_ptr<Launch> launch_;
  ros::NodeHandle handle_;
  ros::ServiceClient predict_;
};

TEST_F(PosePredictorNodeTest, ServicePredictsTheObjectsLeftOut) {
  const std::string cup = demonstration_.objects()[0].type;
  const std::string plate = demonstration_.objects()[3].type;
  asr_msgs::PredictPoses service;
  service.request.instances = {instanceWithout(5, {cup, plate})};
  service.request.samples = 40;
  service.request.seed = 2;
  ASSERT_TRUE(predict_.call(service));
  ASSERT_EQ(service.response.clouds.size(), 1u) << service.response.message;
  const asr_msgs::PredictedPoseCloud& cloud = service.response.clouds[0];
  EXPECT_EQ(cloud.scene, "gedeck");
  EXPECT_EQ(cloud.header.frame_id, "map");
  std::set<std::string> predicted;
  for (const auto& object : cloud.objects) {
    predicted.insert(object.type);
    EXPECT_EQ(object.poses.size(), 40u);
    EXPECT_FALSE(object.path.empty());
  }
  EXPECT_EQ(predicted, (std::set<std::string>{cup, plate}));

  // The true pose of a left-out object is among its predictions, to a few centimetres.
  const asr_common::ObjectEstimate truth = demonstration_.configuration(5)[0];
  for (const auto& object : cloud.objects) {
    if (object.type != truth.key.type)
      continue;
    double nearest = INFINITY;
    for (const auto& pose : object.poses) {
      nearest = std::min(nearest, std::hypot(pose.position.x - truth.pose.position.x(),
                                             pose.position.y - truth.pose.position.y(),
                                             pose.position.z - truth.pose.position.z()));
    }
    EXPECT_LT(nearest, 0.05);
  }
}

TEST_F(PosePredictorNodeTest, PredictsForTheLatestInstancesOnTheTopic) {
  ros::Publisher instances = handle_.advertise<asr_msgs::SceneInstanceList>("scene_instances", 1);
  std::size_t clouds = 0;
  ros::Subscriber subscriber = handle_.subscribe<asr_msgs::PredictedPoseCloud>(
      "predicted_poses", 10, [&](const asr_msgs::PredictedPoseCloud::ConstPtr&) { ++clouds; });
  ASSERT_TRUE(waitFor(
      [&] { return instances.getNumSubscribers() > 0 && subscriber.getNumPublishers() > 0; }, 30));
  asr_msgs::SceneInstanceList list;
  list.header.frame_id = "map";
  list.instances = {instanceWithout(9, {demonstration_.objects()[2].type})};
  instances.publish(list);
  EXPECT_TRUE(waitFor([&] { return clouds > 0; }, 10));

  // An empty request predicts for the latest instances received.
  asr_msgs::PredictPoses service;
  ASSERT_TRUE(predict_.call(service));
  ASSERT_EQ(service.response.clouds.size(), 1u) << service.response.message;
  ASSERT_EQ(service.response.clouds[0].objects.size(), 1u);
  EXPECT_EQ(service.response.clouds[0].objects[0].type, demonstration_.objects()[2].type);
  EXPECT_EQ(service.response.clouds[0].objects[0].poses.size(),
            100u);  // samples in pose_predictor.yaml
}

TEST_F(PosePredictorNodeTest, NothingToPredictFromIsSaid) {
  asr_msgs::PredictPoses none;
  ASSERT_TRUE(predict_.call(none));
  EXPECT_TRUE(none.response.clouds.empty());
  EXPECT_NE(none.response.message.find("no scene instance"), std::string::npos)
      << none.response.message;

  asr_msgs::PredictPoses complete;
  complete.request.instances = {instanceWithout(5, {})};
  ASSERT_TRUE(predict_.call(complete));
  EXPECT_TRUE(complete.response.clouds.empty());
  EXPECT_NE(complete.response.message.find("nothing to predict"), std::string::npos)
      << complete.response.message;

  asr_msgs::PredictPoses unknown;
  unknown.request.instances = {instanceWithout(5, {demonstration_.objects()[0].type})};
  unknown.request.instances[0].scene = "Kuehlschrank";
  ASSERT_TRUE(predict_.call(unknown));
  EXPECT_TRUE(unknown.response.clouds.empty());
  EXPECT_NE(unknown.response.message.find("Kuehlschrank"), std::string::npos)
      << unknown.response.message;
  EXPECT_TRUE(launch_->process().running());
}

}  // namespace
}  // namespace asr_pose_prediction

int main(int argc, char** argv) {
  return asr_common::testing::runRostests(argc, argv, "pose_predictor_rostest");
}
