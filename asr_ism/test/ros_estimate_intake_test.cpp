#include <gtest/gtest.h>
#include <ros/time.h>
#include <tf2_ros/buffer.h>

#include <cmath>

#include "asr_common/ros/callback_guard.hpp"
#include "asr_common/ros/object_estimate_message.hpp"
#include "asr_common/testing/transform_message.hpp"
#include "asr_ism/common_types.hpp"
#include "asr_ism/ros/estimate_intake.hpp"

namespace asr_ism::ros_interface {

using asr_common::ros_interface::fromEstimateMessage;
using asr_common::ros_interface::guardCallback;
using asr_common::ros_interface::toEstimateMessage;
using asr_common::testing::transformMessage;
namespace {

asr_msgs::ObjectEstimate cupIn(const std::string& frame) {
  asr_msgs::ObjectEstimate message;
  message.header.frame_id = frame;
  message.header.stamp = ros::Time(100.0);
  message.type = "Cup";
  message.instance_id = "1";
  message.pose.pose.position.x = 1.0;
  message.pose.pose.orientation.w = 1.0;
  return message;
}

TEST(RosObjectEstimateMessage, RoundTrip) {
  const ObjectEstimate estimate{
      {"Plate", "7"},
      Pose(Eigen::Vector3d(0.1, -0.2, 0.75),
           Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ())))};
  std_msgs::Header header;
  header.frame_id = "map";
  const ObjectEstimate back = fromEstimateMessage(toEstimateMessage(estimate, header));
  EXPECT_EQ(back.key, estimate.key);
  EXPECT_EQ(back.pose.position, estimate.pose.position);
  EXPECT_EQ(back.pose.orientation.coeffs(), estimate.pose.orientation.coeffs());
}

TEST(RosObjectEstimateMessage, BadEstimatesNameTheEstimate) {
  auto empty_type = cupIn("camera");
  empty_type.type.clear();
  auto nan_position = cupIn("camera");
  nan_position.pose.pose.position.y = std::nan("");
  auto zero_quaternion = cupIn("camera");
  zero_quaternion.pose.pose.orientation.w = 0.0;
  auto unnormalised = cupIn("camera");
  unnormalised.pose.pose.orientation.w = 2.0;
  for (const auto& [message, expected] :
       {std::pair{empty_type, "type is empty"}, std::pair{nan_position, "not finite"},
        std::pair{zero_quaternion, "zero quaternion"}, std::pair{unnormalised, "not normalised"}}) {
    try {
      fromEstimateMessage(message);
      ADD_FAILURE() << "accepted: " << expected;
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find(expected), std::string::npos) << error.what();
      EXPECT_NE(std::string(error.what()).find("frame 'camera'"), std::string::npos);
    }
  }
}

TEST(RosEstimateIntake, TransformsIntoTheFixedFrameAndCountsRejections) {
  ros::Time::init();
  tf2_ros::Buffer buffer;
  // The camera looks along the map's x axis turned by 90 degrees about z.
  const Pose camera_in_map(Eigen::Vector3d(0, 0, 1.5),
                           Eigen::Quaterniond(std::sqrt(0.5), 0.0, 0.0, std::sqrt(0.5)));
  buffer.setTransform(transformMessage("map", "camera", camera_in_map, ros::Time(100.0)), "test",
                      true);

  EstimateIntake intake(buffer, "map", ros::Duration(0.0));
  const auto in_map = intake.accept(cupIn("camera"));
  ASSERT_TRUE(in_map.has_value());
  EXPECT_NEAR(in_map->pose.position.x(), 0.0, 1e-12);
  EXPECT_NEAR(in_map->pose.position.y(), 1.0, 1e-12);
  EXPECT_NEAR(in_map->pose.position.z(), 1.5, 1e-12);
  EXPECT_NEAR(angleBetween(in_map->pose.orientation,
                           Eigen::Quaterniond(std::sqrt(0.5), 0.0, 0.0, std::sqrt(0.5))),
              0.0, 1e-12);
  // In the fixed frame, or without a frame: taken as they are.
  EXPECT_EQ(intake.accept(cupIn("map"))->pose.position.x(), 1.0);
  EXPECT_EQ(intake.accept(cupIn(""))->pose.position.x(), 1.0);

  auto nan_estimate = cupIn("camera");
  nan_estimate.pose.pose.orientation.x = std::nan("");
  EXPECT_FALSE(intake.accept(nan_estimate).has_value());
  EXPECT_FALSE(intake.accept(cupIn("unknown_frame")).has_value());
  EXPECT_EQ(intake.acceptedCount(), 3u);
  EXPECT_EQ(intake.rejectedCount(), 2u);
  EXPECT_EQ(intake.rejectedByReason().at("invalid estimate"), 1u);
  EXPECT_EQ(intake.rejectedByReason().at("no transform"), 1u);
}

TEST(RosEstimateIntake, FarAwayEstimatesAreRejectedWithTheirReason) {
  // An estimate 1e5 m from the origin used to reach the voting space and end the recogniser.
  ros::Time::init();
  tf2_ros::Buffer buffer;
  const Pose far_camera(Eigen::Vector3d(999.5, 0, 0), Eigen::Quaterniond::Identity());
  buffer.setTransform(transformMessage("map", "far_camera", far_camera, ros::Time(100.0)), "test",
                      true);
  EstimateIntake intake(buffer, "map", ros::Duration(0.0));
  auto far = cupIn("map");
  far.pose.pose.position.x = 1e5;
  EXPECT_FALSE(intake.accept(far).has_value());
  // Near the camera, but beyond the limit once in the fixed frame.
  EXPECT_FALSE(intake.accept(cupIn("far_camera")).has_value());
  EXPECT_EQ(intake.rejectedByReason().at("invalid estimate"), 2u);
  auto near = cupIn("far_camera");
  near.pose.pose.position.x = 0.4;
  ASSERT_TRUE(intake.accept(near).has_value());
}

TEST(RosCallbackGuard, NoExceptionLeavesACallback) {
  ros::Time::init();
  const auto nothing = [] {};
  static_assert(noexcept(guardCallback("test", nothing)));
  int runs = 0;
  EXPECT_TRUE(guardCallback("test: fine", [&] { ++runs; }));
  EXPECT_FALSE(guardCallback("test: bad input", [&] {
    ++runs;
    throw InputError("voting space: a vote lies too far from the origin");
  }));
  EXPECT_FALSE(guardCallback("test: bug", [&] {
    ++runs;
    throw std::out_of_range("vector::at");
  }));
  EXPECT_FALSE(guardCallback("test: anything", [&] {
    ++runs;
    throw 42;
  }));
  EXPECT_EQ(runs, 4);
}

}  // namespace
}  // namespace asr_ism::ros_interface
