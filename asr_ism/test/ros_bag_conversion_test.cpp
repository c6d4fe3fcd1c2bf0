// Converting a rosbag of object estimates into a demonstration file, without a master: a bag
// written here with estimates in a camera frame, its transform on /tf_static, and bad estimates.

#include <asr_msgs/ObjectEstimateList.h>
#include <gtest/gtest.h>
#include <rosbag/bag.h>
#include <tf2_msgs/TFMessage.h>

#include <limits>

#include "asr_common/ros/object_estimate_message.hpp"
#include "asr_common/testing/input_error_of.hpp"
#include "asr_common/testing/temp_dir.hpp"
#include "asr_common/testing/transform_message.hpp"
#include "asr_ism/ros/bag_conversion.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"
#include "asr_ism/synthetic_demonstration.hpp"

namespace asr_ism::ros_interface {

using asr_common::ros_interface::toEstimateMessage;
namespace {

using asr_common::testing::inputErrorOf;

class BagConversionTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ros::Time::init();
    // The camera sits 1 m above the map origin, turned a quarter about z.
    camera_in_map_ =
        Pose(Eigen::Vector3d(0, 0, 1),
             Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ())));
    rosbag::Bag bag(bag_, rosbag::bagmode::Write);
    tf2_msgs::TFMessage transforms;
    transforms.transforms.push_back(
        asr_common::testing::transformMessage("map", "camera", camera_in_map_, ros::Time(100)));
    bag.write("/tf_static", ros::Time(100), transforms);
    for (std::size_t step = 0; step < demonstration_.stepCount(); ++step) {
      asr_msgs::ObjectEstimateList list;
      std_msgs::Header header;
      header.frame_id = "camera";
      header.stamp = ros::Time(101 + step);
      for (const ObjectEstimate& estimate : demonstration_.configuration(step)) {
        // Seen from the camera: the pose relative to it.
        ObjectEstimate seen = estimate;
        seen.pose = relativePose(camera_in_map_, estimate.pose);
        list.objects.push_back(toEstimateMessage(seen, header));
      }
      if (step == 1) {  // one bad estimate and one in a frame the bag has no transform for
        asr_msgs::ObjectEstimate bad = list.objects[0];
        bad.pose.pose.position.x = std::numeric_limits<double>::quiet_NaN();
        asr_msgs::ObjectEstimate lost = list.objects[1];
        lost.header.frame_id = "nowhere";
        list.objects = {bad, lost};
      }
      bag.write("/objects", header.stamp, list);
    }
    bag.close();
  }

  asr_common::testing::TempDir dir_{"asr_bag_conversion"};
  std::string bag_ = dir_.file("demo.bag");
  Demonstration demonstration_ = makeSyntheticDemonstration(3, 5, 2, "tray");
  Pose camera_in_map_;
};

TEST_F(BagConversionTest, EveryMessageBecomesASetInTheFixedFrame) {
  const std::string out = dir_.file("demo.sqlite");
  const BagConversion conversion = convertBagToDemonstration(bag_, "/objects", out, "tray", "map");
  EXPECT_EQ(conversion.messages, 5u);
  EXPECT_EQ(conversion.configurations, 4u);  // set 1 had nothing valid left
  EXPECT_EQ(conversion.rejected, 2u);
  const Demonstration read = sqlite::readDemonstration(out, "tray");
  ASSERT_EQ(read.stepCount(), 4u);
  const std::size_t original_steps[] = {0, 2, 3, 4};
  for (std::size_t step = 0; step < 4; ++step) {
    const Configuration expected = demonstration_.configuration(original_steps[step]);
    const Configuration actual = read.configuration(step);
    ASSERT_EQ(actual.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
      const auto found = std::find_if(actual.begin(), actual.end(),
                                      [&](const auto& e) { return e.key == expected[i].key; });
      ASSERT_NE(found, actual.end());
      EXPECT_LT((found->pose.position - expected[i].pose.position).norm(), 1e-9);
      EXPECT_LT(angleBetween(found->pose.orientation, expected[i].pose.orientation), 1e-6);
    }
  }
}

TEST_F(BagConversionTest, BadInputIsNamed) {
  const std::string out = dir_.file("out.sqlite");
  EXPECT_NE(inputErrorOf([&] {
              convertBagToDemonstration(bag_, "/nothing", out, "tray", "map");
            }).find("/nothing"),
            std::string::npos);
  EXPECT_NE(inputErrorOf([&] {
              convertBagToDemonstration(bag_, "/tf_static", out, "tray", "map");
            }).find("not asr_msgs/ObjectEstimateList"),
            std::string::npos);
  const std::string missing = dir_.file("missing.bag");
  EXPECT_NE(inputErrorOf([&] {
              convertBagToDemonstration(missing, "/objects", out, "tray", "map");
            }).find(missing),
            std::string::npos);
}

}  // namespace
}  // namespace asr_ism::ros_interface
