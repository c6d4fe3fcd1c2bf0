// A rosbag of rendered images replayed into apriltag_detector (rostest), in the setting of the
// issue's accuracy figures: a board carrying one 10 cm tag, rendered by the simulated camera from
// known camera poses 0.5 to 1.5 m away and 0 to 60 degrees off-axis. The test writes the board's
// tag map and a bag of the images with their CameraInfo into a temporary folder, starts the
// detector on that map, replays the bag with `rosbag play`, and compares the estimates the node
// publishes with the poses the images were rendered from: every image answered with its stamp,
// the board found up to 1 m, the median error at 1 m within 1 cm and 2 degrees, and no estimate
// far from the truth at any distance.
#include <asr_msgs/ObjectEstimateList.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <rosbag/bag.h>

#include <algorithm>
#include <fstream>
#include <map>

#include "asr_common/child_process.hpp"
#include "asr_common/ros/object_estimate_message.hpp"
#include "asr_common/testing/rostest_support.hpp"
#include "asr_common/testing/temp_dir.hpp"
#include "asr_robot_model/robot_description.hpp"
#include "asr_robot_model/ros/camera_messages.hpp"
#include "asr_robot_model/tag_camera_sim.hpp"
#include "asr_robot_model/testing/tag_scene.hpp"

namespace asr_robot_model {
namespace {

using asr_common::testing::waitFor;

constexpr double kDegree = M_PI / 180.0;

/// One rendered image: where the camera was.
struct Frame {
  asr_common::Pose camera;
  double distance;
};

double median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

/// The board's tag map in the documented format (config/tag_map.yaml).
void writeTagMap(const std::string& path, const testing::TagBoard& board) {
  const TagPlacement& tag = board.tags.tags.at(0);
  std::ofstream file(path);
  file << "version: 1\nfamily: " << board.tags.family << "\ntags:\n  - {id: " << tag.id
       << ", object: {type: " << tag.object.type << ", id: \"" << tag.object.id
       << "\"}, edge_length: " << tag.edge_length
       << ",\n     pose: {position: {x: " << tag.pose.position.x()
       << ", y: " << tag.pose.position.y() << ", z: " << tag.pose.position.z()
       << "}, orientation: {x: 0, y: 0, z: 0, w: 1}}}\n";
}

/// The views rendered into a bag at `path`, 0.25 s apart, each CameraInfo 10 ms before its
/// image (the two topics travel on separate connections).
std::map<ros::Time, Frame> writeBag(const std::string& path, const testing::TagBoard& board) {
  const TagCameraSim camera(board.world, board.tags, {});
  std::map<ros::Time, Frame> by_stamp;
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  unsigned seed = 0;
  for (const double distance : {0.5, 1.0, 1.5})
    for (const double off_axis : {0.0, 20.0, 40.0, 60.0})
      for (const double azimuth : {0.4, 2.5}) {
        const asr_common::Pose view = testing::viewOf(board.centre(), board.face_normal, distance,
                                                      off_axis * kDegree, azimuth + off_axis);
        std_msgs::Header header;
        header.frame_id = kCameraFrame;
        header.stamp = ros::Time(1000.0 + 0.25 * by_stamp.size());
        bag.write("/camera/camera_info", header.stamp - ros::Duration(0.01),
                  ros_interface::toCameraInfoMessage(camera.settings().camera, header));
        bag.write("/camera/image_raw", header.stamp,
                  ros_interface::toImageMessage(camera.render(view, ++seed), header));
        by_stamp[header.stamp] = {view, distance};
      }
  bag.close();
  return by_stamp;
}

TEST(ApriltagBag, ReplayedRenderedImagesGiveTheKnownPoses) {
  ros::NodeHandle handle;
  asr_common::testing::TempDir dir("asr_apriltag_bag");
  const testing::TagBoard board(0.1);
  writeTagMap(dir.file("board_tags.yaml"), board);
  const std::map<ros::Time, Frame> frames = writeBag(dir.file("rendered.bag"), board);

  std::map<ros::Time, asr_msgs::ObjectEstimateList> published;
  ros::Subscriber objects = handle.subscribe<asr_msgs::ObjectEstimateList>(
      "objects", 100,
      [&](const asr_msgs::ObjectEstimateListConstPtr& m) { published[m->header.stamp] = *m; });
  asr_common::ChildProcess detector(
      std::string(ASR_NODE_DIR) + "/apriltag_detector",
      {"__name:=apriltag_detector", "_tag_map:=" + dir.file("board_tags.yaml"),
       "image:=camera/image_raw", "camera_info:=camera/camera_info"},
      dir.file("detector.log"), dir.file("detector.log"));
  ASSERT_TRUE(waitFor([&] { return objects.getNumPublishers() > 0; }, 30))
      << asr_common::testing::fileBytes(dir.file("detector.log"));
  asr_common::ChildProcess play(
      "/usr/bin/rosbag", {"play", "--quiet", "--wait-for-subscribers", dir.file("rendered.bag")},
      dir.file("play.log"), dir.file("play.log"));
  ASSERT_EQ(play.waitForExit(std::chrono::seconds(60)), 0)
      << asr_common::testing::fileBytes(dir.file("play.log"));
  ASSERT_TRUE(waitFor([&] { return published.size() >= frames.size(); }, 10))
      << published.size() << " of " << frames.size() << " images answered";

  std::vector<double> metres_at_1m, degrees_at_1m;
  for (const auto& [stamp, frame] : frames) {
    ASSERT_EQ(published.count(stamp), 1u) << "no estimates for the image of " << stamp;
    const asr_msgs::ObjectEstimateList& list = published.at(stamp);
    ASSERT_LE(list.objects.size(), 1u);
    if (list.objects.empty()) {
      EXPECT_GT(frame.distance, 1.0) << "the board is not found " << frame.distance << " m away";
      continue;
    }
    const asr_msgs::ObjectEstimate& estimate = list.objects[0];
    EXPECT_EQ(estimate.type, "Board");
    EXPECT_EQ(estimate.instance_id, "0");
    EXPECT_EQ(estimate.header.frame_id, kCameraFrame);
    const asr_common::Pose truth = asr_common::relativePose(frame.camera, board.board);
    const asr_common::Pose seen =
        asr_common::ros_interface::fromPoseMessage(estimate.pose.pose, "estimate");
    const double metres = (seen.position - truth.position).norm();
    const double degrees = asr_common::angleBetween(seen.orientation, truth.orientation) / kDegree;
    // Never a wrong pose (the benchmark's worst over these views: 0.8 cm, 5.5 degrees).
    EXPECT_LE(metres, 0.02) << frame.distance << " m";
    EXPECT_LE(degrees, 8.0) << frame.distance << " m";
    if (frame.distance == 1.0) {
      metres_at_1m.push_back(metres);
      degrees_at_1m.push_back(degrees);
    }
  }
  ASSERT_EQ(metres_at_1m.size(), 8u);
  EXPECT_LE(median(metres_at_1m), 0.01);
  EXPECT_LE(median(degrees_at_1m), 2.0);
}

}  // namespace
}  // namespace asr_robot_model

int main(int argc, char** argv) {
  return asr_common::testing::runRostests(argc, argv, "apriltag_bag_rostest");
}
