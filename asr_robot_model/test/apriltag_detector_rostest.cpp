// The AprilTag chain end to end (rostest, robot_sim.launch detector:=apriltag with the shipped
// kitchen): camera_sim's images of the robot's view give the cup on `objects` at its true pose
// in the camera frame, as the core's detector finds it in the same image; detect_objects answers
// the requested types in map; images the test publishes itself show that tags the map does not
// know are counted and that an image of an unreadable encoding leaves the node running.
#include <asr_msgs/DetectObjects.h>
#include <asr_msgs/ObjectEstimateList.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
#include <std_msgs/UInt64.h>

#include <algorithm>
#include <map>

#include "asr_common/ros/object_estimate_message.hpp"
#include "asr_common/testing/rostest_support.hpp"
#include "asr_robot_model/forward_kinematics.hpp"
#include "asr_robot_model/ros/camera_messages.hpp"
#include "asr_robot_model/tag_camera_sim.hpp"
#include "asr_robot_model/tag_detector.hpp"
#include "simulation_probe.hpp"

namespace asr_robot_model {
namespace {

using asr_common::testing::waitFor;

const asr_msgs::ObjectEstimate* find(const asr_msgs::ObjectEstimateList& list,
                                     const std::string& type) {
  for (const auto& estimate : list.objects)
    if (estimate.type == type)
      return &estimate;
  return nullptr;
}

class ApriltagDetectorTest : public ::testing::Test {
 protected:
  void SetUp() override {
    objects_ = handle_.subscribe<asr_msgs::ObjectEstimateList>(
        "objects", 10,
        [this](const asr_msgs::ObjectEstimateListConstPtr& m) { published_.push_back(*m); });
    images_ = handle_.subscribe<sensor_msgs::Image>(
        "camera/image_raw", 10,
        [this](const sensor_msgs::ImageConstPtr& m) { images_by_stamp_[m->header.stamp] = *m; });
    unknown_ = handle_.subscribe<std_msgs::UInt64>(
        "apriltag_detector/unknown_tags", 10,
        [this](const std_msgs::UInt64ConstPtr& m) { unknown_count_ = m->data; });
    detect_ = handle_.serviceClient<asr_msgs::DetectObjects>("detect_objects");
    ASSERT_TRUE(detect_.waitForExistence(ros::Duration(60))) << "apriltag_detector did not start";
    ASSERT_TRUE(probe_.waitForDriver(30));
    ASSERT_TRUE(waitFor([&] { return !published_.empty(); }, 60)) << "no objects published";
  }

  /// The latest published list that shows the cup.
  const asr_msgs::ObjectEstimateList* latestWithCup() {
    waitFor([&] { return !published_.empty() && find(published_.back(), "Cup"); }, 30);
    return !published_.empty() && find(published_.back(), "Cup") ? &published_.back() : nullptr;
  }

  const WorldObject& cup() const {
    return *std::find_if(kitchen_.world.objects.begin(), kitchen_.world.objects.end(),
                         [](const WorldObject& o) { return o.key.type == "Cup"; });
  }

  ros::NodeHandle handle_;
  testing::SimulationProbe probe_;
  testing::Kitchen kitchen_;
  ros::ServiceClient detect_;
  ros::Subscriber objects_, images_, unknown_;
  std::vector<asr_msgs::ObjectEstimateList> published_;
  std::map<ros::Time, sensor_msgs::Image> images_by_stamp_;
  std::uint64_t unknown_count_ = 0;
};

TEST_F(ApriltagDetectorTest, TheRenderedViewGivesTheCupWhereItStands) {
  const asr_msgs::ObjectEstimateList* list = latestWithCup();
  ASSERT_NE(list, nullptr) << "the cup's tag was not found in the start view";
  const asr_msgs::ObjectEstimate& estimate = *find(*list, "Cup");
  EXPECT_EQ(estimate.header.frame_id, kCameraFrame);
  EXPECT_EQ(estimate.instance_id, "0");
  const asr_common::Pose camera = cameraPose(kitchen_.robot, probe_.state());
  const asr_common::Pose truth = asr_common::relativePose(camera, cup().box.pose);
  const asr_common::Pose seen =
      asr_common::ros_interface::fromPoseMessage(estimate.pose.pose, "estimate");
  EXPECT_LE((seen.position - truth.position).norm(), 0.03);
  EXPECT_LE(asr_common::angleBetween(seen.orientation, truth.orientation), 0.1);
  EXPECT_GT(estimate.pose.covariance[0], 0.0);

  // The core's detector finds the same objects in the very image the node was given.
  ASSERT_TRUE(waitFor([&] { return images_by_stamp_.count(list->header.stamp) > 0; }, 10));
  bool converted = true;
  const GreyImage image =
      ros_interface::greyFromImageMessage(images_by_stamp_[list->header.stamp], converted);
  EXPECT_FALSE(converted);
  const TagDetector detector(loadTagMap(defaultTagMap()));
  const TagDetections found = detector.detect(image, CameraIntrinsics::defaults());
  ASSERT_EQ(found.objects.size(), list->objects.size());
  for (const ObjectDetection& object : found.objects)
    EXPECT_NE(find(*list, object.key.type), nullptr) << object.key.type;
}

TEST_F(ApriltagDetectorTest, DetectObjectsAnswersTheRequestedTypesInMap) {
  ASSERT_NE(latestWithCup(), nullptr);
  asr_msgs::DetectObjects service;
  service.request.types = {"Cup"};
  ASSERT_TRUE(detect_.call(service));
  ASSERT_FALSE(service.response.estimates.objects.empty());
  for (const auto& estimate : service.response.estimates.objects) {
    EXPECT_EQ(estimate.type, "Cup");
    EXPECT_EQ(estimate.header.frame_id, "map");
    const asr_common::Pose seen =
        asr_common::ros_interface::fromPoseMessage(estimate.pose.pose, "estimate");
    EXPECT_LE((seen.position - cup().box.pose.position).norm(), 0.03);
  }
  // From now on only cups are published, until all types are asked for again.
  const std::size_t before = published_.size();
  ASSERT_TRUE(waitFor([&] { return published_.size() > before + 1; }, 30));
  for (const auto& estimate : published_.back().objects)
    EXPECT_EQ(estimate.type, "Cup");
  service.request.types.clear();
  ASSERT_TRUE(detect_.call(service));
  service.request.types = {""};
  EXPECT_FALSE(detect_.call(service));
}

TEST_F(ApriltagDetectorTest, UnknownTagsAreCountedAndUnreadableImagesDoNotStopTheNode) {
  ros::Publisher images = handle_.advertise<sensor_msgs::Image>("camera/image_raw", 10);
  ASSERT_TRUE(waitFor([&] { return images.getNumSubscribers() > 0; }, 10));
  std_msgs::Header header;
  header.frame_id = kCameraFrame;
  header.stamp = probe_.clock();

  sensor_msgs::Image unreadable;
  unreadable.header = header;
  unreadable.width = 640;
  unreadable.height = 480;
  unreadable.encoding = "32FC1";
  unreadable.step = 640 * 4;
  unreadable.data.assign(640 * 480 * 4, 0);
  images.publish(unreadable);

  // The kitchen seen by the robot, but with the cup's tag 0 replaced by one the map lacks.
  TagMap strange = loadTagMap(defaultTagMap());
  TagPlacement cup_tag = strange.tags.at(0);
  strange.tags.erase(0);
  cup_tag.id = 300;
  strange.tags[300] = cup_tag;
  const TagCameraSim camera(kitchen_.world, strange, {});
  const GreyImage image = camera.render(cameraPose(kitchen_.robot, probe_.state()), 5);
  int tick = 0;
  ASSERT_TRUE(waitFor(
      [&] {
        if (tick++ % 20 == 0)  // every 0.2 s
          images.publish(ros_interface::toImageMessage(image, header));
        return unknown_count_ > 0;
      },
      30));
  const std::size_t before = published_.size();
  EXPECT_TRUE(waitFor([&] { return published_.size() > before + 2; }, 30))
      << "the detector stopped publishing";
}

}  // namespace
}  // namespace asr_robot_model

int main(int argc, char** argv) {
  return asr_common::testing::runRostests(argc, argv, "apriltag_detector_rostest");
}
