// object_detector_sim end to end on simulated time (rostest, robot_sim.launch with the shipped
// kitchen): the service answers what the core's detection simulator sees from the robot's
// camera, charges detection_seconds_per_type per type on /clock, publishes the estimates on
// `objects`, and refuses an unknown type.
#include <asr_msgs/DetectObjects.h>
#include <asr_msgs/ObjectEstimateList.h>
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <algorithm>
#include <set>

#include "asr_common/testing/rostest_support.hpp"
#include "asr_robot_model/detection_simulator.hpp"
#include "asr_robot_model/forward_kinematics.hpp"
#include "simulation_probe.hpp"

namespace asr_robot_model {
namespace {

using asr_common::testing::waitFor;

class ObjectDetectorSimTest : public ::testing::Test {
 protected:
  void SetUp() override {
    objects_ = handle_.subscribe<asr_msgs::ObjectEstimateList>(
        "objects", 10,
        [this](const asr_msgs::ObjectEstimateListConstPtr& m) { published_.push_back(*m); });
    detect_ = handle_.serviceClient<asr_msgs::DetectObjects>("detect_objects");
    ASSERT_TRUE(detect_.waitForExistence(ros::Duration(60))) << "object_detector_sim did not start";
    ASSERT_TRUE(probe_.waitForDriver(30));
    ASSERT_TRUE(waitFor([&] { return objects_.getNumPublishers() > 0; }, 30));
  }

  // What the core sees from the robot's current camera pose (the nodes' default settings).
  Detections expected(const std::vector<std::string>& types) {
    DetectionSimulator simulator(kitchen_.world, kitchen_.map, DetectionSettings{}, 1);
    return simulator.detect(cameraPose(kitchen_.robot, probe_.state()), types);
  }

  static std::set<std::string> keysOf(const asr_msgs::ObjectEstimateList& list) {
    std::set<std::string> keys;
    for (const auto& estimate : list.objects)
      keys.insert(estimate.type + ":" + estimate.instance_id);
    return keys;
  }

  ros::NodeHandle handle_;
  testing::SimulationProbe probe_;
  testing::Kitchen kitchen_;
  ros::ServiceClient detect_;
  ros::Subscriber objects_;
  std::vector<asr_msgs::ObjectEstimateList> published_;
};

TEST_F(ObjectDetectorSimTest, AnswersWhatTheCameraSeesAndChargesTheTimePerType) {
  std::set<std::string> types;
  for (const WorldObject& object : kitchen_.world.objects)
    types.insert(object.key.type);
  const Detections reference = expected({});
  // The kitchen's start view sees the breakfast on the table, not the rest.
  std::set<std::string> seen;
  for (const auto& estimate : reference.detected)
    seen.insert(estimate.key.type + ":" + estimate.key.id);
  EXPECT_EQ(seen, (std::set<std::string>{"Cup:0", "PlateDeep:0"}));

  const ros::Time before = probe_.clock();
  asr_msgs::DetectObjects service;
  ASSERT_TRUE(service.request.types.empty());
  ASSERT_TRUE(detect_.call(service));
  EXPECT_EQ(keysOf(service.response.estimates), seen);
  for (const auto& estimate : service.response.estimates.objects) {
    const auto truth = std::find_if(reference.detected.begin(), reference.detected.end(),
                                    [&](const auto& e) { return e.key.type == estimate.type; });
    ASSERT_NE(truth, reference.detected.end());
    EXPECT_NEAR(estimate.pose.pose.position.x, truth->pose.position.x(), 1e-9);
    EXPECT_NEAR(estimate.pose.pose.position.z, truth->pose.position.z(), 1e-9);
    EXPECT_EQ(estimate.header.frame_id, "map");
  }
  const double seconds = 3.0 * static_cast<double>(types.size());
  EXPECT_DOUBLE_EQ(service.response.seconds, seconds);
  const ros::Time after = probe_.waitForClock(before + ros::Duration(seconds));
  EXPECT_NEAR((after - before).toSec(), seconds, 1e-6);
  EXPECT_EQ(service.response.estimates.header.stamp, after);
  // The same estimates on the topic real detectors use.
  ASSERT_TRUE(waitFor([&] { return !published_.empty(); }, 10));
  EXPECT_EQ(keysOf(published_.back()), seen);
}

TEST_F(ObjectDetectorSimTest, RequestedTypesOnlyAndTheirTime) {
  const ros::Time before = probe_.clock();
  asr_msgs::DetectObjects service;
  service.request.types = {"Cup", "CoffeeBox"};
  ASSERT_TRUE(detect_.call(service));
  EXPECT_EQ(keysOf(service.response.estimates), (std::set<std::string>{"Cup:0"}));
  EXPECT_NEAR((probe_.waitForClock(before + ros::Duration(6.0)) - before).toSec(), 6.0, 1e-6);
}

TEST_F(ObjectDetectorSimTest, UnknownOrEmptyTypesAreRefusedWithoutTakingTime) {
  const ros::Time before = probe_.clock();
  asr_msgs::DetectObjects service;
  service.request.types = {"NoSuchObject"};
  EXPECT_FALSE(detect_.call(service));
  service.request.types = {""};
  EXPECT_FALSE(detect_.call(service));
  EXPECT_EQ(probe_.clock(), before);
}

}  // namespace
}  // namespace asr_robot_model

int main(int argc, char** argv) {
  return asr_common::testing::runRostests(argc, argv, "object_detector_sim_rostest");
}
