// The recorder and replay_demonstration nodes end to end, with a ROS master (rostest): a real
// recording replayed into the recorder gives a file whose sets equal the source's; what was in
// the file stays; malformed estimates are rejected and counted while the node keeps recording.

#include <asr_msgs/ObjectEstimateList.h>
#include <asr_msgs/RecordConfiguration.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <std_msgs/UInt32.h>

#include <filesystem>
#include <limits>
#include <memory>

#include "asr_common/child_process.hpp"
#include "asr_common/ros/object_estimate_message.hpp"
#include "asr_common/testing/recordings_skip.hpp"
#include "asr_common/testing/rostest_support.hpp"
#include "asr_common/testing/temp_dir.hpp"
#include "asr_ism/ros/bag_conversion.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"
#include "asr_ism/sqlite/demonstration_writer.hpp"
#include "asr_ism/synthetic_demonstration.hpp"

namespace asr_ism {
namespace {

using asr_common::ChildProcess;
using asr_common::testing::Launch;
using asr_common::testing::TempDir;
using asr_common::testing::waitFor;

std::string node(const std::string& name) {
  return std::string(ASR_NODE_DIR) + "/" + name;
}

// Counts published on a latched UInt32 topic.
struct Counter {
  std::uint32_t value = 0;
  ros::Subscriber subscriber;
  Counter(ros::NodeHandle& handle, const std::string& topic)
      : subscriber(handle.subscribe<std_msgs::UInt32>(
            topic, 10, [this](const std_msgs::UInt32::ConstPtr& count) { value = count->data; })) {}
};

class RecorderNodeTest : public ::testing::Test {
 protected:
  void startRecorder(const std::string& mode) {
    // As a user starts it, with the shipped parameter file.
    recorder_ = std::make_unique<Launch>(
        "learn.launch",
        std::vector<std::string>{"demonstration_file:=" + output_, "scene:=Getraenke_Regal",
                                 "mode:=" + mode},
        dir_.file("learn_launch.log"));
    ros::ServiceClient client =
        handle_.serviceClient<asr_msgs::RecordConfiguration>("record_configuration");
    ASSERT_TRUE(client.waitForExistence(ros::Duration(30))) << "recorder did not start";
  }

  TempDir dir_{"asr_recorder_rostest"};
  std::string output_ = dir_.file("recorded.sqlite");
  ros::NodeHandle handle_;
  std::unique_ptr<Launch> recorder_;
};

TEST_F(RecorderNodeTest, AReplayedRecordingIsRecordedSetForSetAndTheFileKeepsItsRows) {
  REQUIRE_RECORDINGS();
  const std::string source = asr_common::testing::recording("story_2.sqlite");
  const Demonstration original = sqlite::readDemonstration(source, "Getraenke_Regal");
  // Something the user recorded before: it must survive.
  const Demonstration earlier = makeSyntheticDemonstration(3, 4, 1, "earlier");
  sqlite::appendDemonstration(output_, earlier);

  startRecorder("message");
  Counter recorded(handle_, "recorder/recorded_sets");
  Launch replay("replay.launch",
                {"demonstration_file:=" + source, "scene:=Getraenke_Regal", "rate:=40"},
                dir_.file("replay_launch.log"));
  ASSERT_TRUE(waitFor([&] { return recorded.value == original.stepCount(); }, 90))
      << recorded.value << " of " << original.stepCount() << " sets recorded";
  // The launch ends by itself after the last set, and says nothing about a required node.
  EXPECT_EQ(replay.process().waitForExit(std::chrono::seconds(60)), 0);
  EXPECT_EQ(asr_common::testing::fileBytes(dir_.file("replay_launch.log")).find("REQUIRED"),
            std::string::npos);
  recorder_->stop();

  const Demonstration copy = sqlite::readDemonstration(output_, "Getraenke_Regal");
  ASSERT_EQ(copy.stepCount(), original.stepCount());
  for (std::size_t step = 0; step < original.stepCount(); ++step) {
    const Configuration expected = original.configuration(step);
    const Configuration actual = copy.configuration(step);
    ASSERT_EQ(actual.size(), expected.size()) << "set " << step;
    for (const ObjectEstimate& estimate : expected) {
      const auto found = std::find_if(actual.begin(), actual.end(),
                                      [&](const auto& e) { return e.key == estimate.key; });
      ASSERT_NE(found, actual.end()) << estimate.key.toString() << " in set " << step;
      // Through a float64 message and back: equal to rounding.
      EXPECT_LT((found->pose.position - estimate.pose.position).norm(), 1e-9);
      EXPECT_LT(angleBetween(found->pose.orientation, estimate.pose.orientation), 1e-6);
    }
  }
  const Demonstration kept = sqlite::readDemonstration(output_, "earlier");
  EXPECT_EQ(kept.stepCount(), earlier.stepCount());
}

TEST_F(RecorderNodeTest, MalformedEstimatesAreRejectedCountedAndRecordingGoesOn) {
  startRecorder("message");
  Counter recorded(handle_, "recorder/recorded_sets");
  Counter rejected(handle_, "recorder/rejected_estimates");
  ros::Publisher objects = handle_.advertise<asr_msgs::ObjectEstimateList>("objects", 10);
  ASSERT_TRUE(waitFor([&] { return objects.getNumSubscribers() > 0; }, 30));

  std_msgs::Header header;
  header.frame_id = "map";
  header.stamp = ros::Time::now();
  const ObjectEstimate valid{{"Cup", "0"},
                             Pose(Eigen::Vector3d(1, 2, 0.8), Eigen::Quaterniond::Identity())};
  asr_msgs::ObjectEstimate nan = asr_common::ros_interface::toEstimateMessage(valid, header);
  nan.type = "Plate";
  nan.pose.pose.position.y = std::numeric_limits<double>::quiet_NaN();
  asr_msgs::ObjectEstimate zero = asr_common::ros_interface::toEstimateMessage(valid, header);
  zero.type = "Knife";
  zero.pose.pose.orientation.w = 0.0;
  asr_msgs::ObjectEstimate empty = asr_common::ros_interface::toEstimateMessage(valid, header);
  empty.type = "";
  asr_msgs::ObjectEstimateList list;
  list.objects = {nan, zero, empty, asr_common::ros_interface::toEstimateMessage(valid, header)};
  objects.publish(list);
  ASSERT_TRUE(waitFor([&] { return rejected.value == 3 && recorded.value == 1; }, 10))
      << rejected.value << " rejected, " << recorded.value << " recorded";
  EXPECT_TRUE(recorder_->process().running());

  // The service records a given configuration too, under its own scene if named.
  ros::ServiceClient client =
      handle_.serviceClient<asr_msgs::RecordConfiguration>("record_configuration");
  asr_msgs::RecordConfiguration service;
  service.request.scene = "by_service";
  service.request.objects = {asr_common::ros_interface::toEstimateMessage(valid, header)};
  ASSERT_TRUE(client.call(service));
  EXPECT_TRUE(service.response.success) << service.response.message;
  EXPECT_EQ(service.response.object_count, 1u);
  recorder_->stop();
  EXPECT_EQ(sqlite::readDemonstration(output_, "Getraenke_Regal").stepCount(), 1u);
  EXPECT_EQ(sqlite::readDemonstration(output_, "by_service").stepCount(), 1u);
}

TEST_F(RecorderNodeTest, ABadParameterStopsTheNodeNamingItAndRecordsNothing) {
  const std::string err = dir_.file("bad_recorder.err");
  ChildProcess missing(node("recorder"), {"__name:=bad_recorder", "_scene:=x"}, "", err);
  EXPECT_EQ(missing.waitForExit(std::chrono::seconds(20)), 1);
  EXPECT_NE(asr_common::testing::fileBytes(err).find("demonstration_file"), std::string::npos)
      << asr_common::testing::fileBytes(err);
  ChildProcess bad_mode(
      node("recorder"),
      {"__name:=bad_recorder", "_scene:=x", "_demonstration_file:=" + output_, "_mode:=sometimes"},
      "", err);
  EXPECT_EQ(bad_mode.waitForExit(std::chrono::seconds(20)), 1);
  EXPECT_NE(asr_common::testing::fileBytes(err).find("mode"), std::string::npos)
      << asr_common::testing::fileBytes(err);
  EXPECT_FALSE(std::filesystem::exists(output_)) << "nothing recorded, no file created";
}

TEST_F(RecorderNodeTest, AReplayIntoABagHoldsEverySetAndDoesNotOverwriteABag) {
  REQUIRE_RECORDINGS();
  const std::string source = asr_common::testing::recording("story_2.sqlite");
  const Demonstration original = sqlite::readDemonstration(source, "Getraenke_Regal");
  const std::string bag = dir_.file("replay.bag");
  Launch replay("replay.launch",
                {"demonstration_file:=" + source, "scene:=Getraenke_Regal", "rate:=100",
                 "record_bag:=true", "bag:=" + bag},
                dir_.file("bag_launch.log"));
  ASSERT_EQ(replay.process().waitForExit(std::chrono::seconds(120)), 0);
  const std::string converted = dir_.file("from_bag.sqlite");
  const auto conversion = ros_interface::convertBagToDemonstration(bag, "/objects", converted,
                                                                   "Getraenke_Regal", "map");
  EXPECT_EQ(conversion.messages, original.stepCount());
  EXPECT_EQ(conversion.rejected, 0u);
  const Demonstration copy = sqlite::readDemonstration(converted, "Getraenke_Regal");
  ASSERT_EQ(copy.stepCount(), original.stepCount());
  for (std::size_t step = 0; step < original.stepCount(); step += 7)
    EXPECT_EQ(copy.configuration(step).size(), original.configuration(step).size()) << step;

  // A second replay into the same bag is refused: the first recording stays as it was.
  const auto size = std::filesystem::file_size(bag);
  const std::string log = dir_.file("bag_again.log");
  Launch again("replay.launch",
               {"demonstration_file:=" + source, "scene:=Getraenke_Regal", "record_bag:=true",
                "bag:=" + bag},
               log);
  ASSERT_EQ(again.process().waitForExit(std::chrono::seconds(60)), 0);
  EXPECT_NE(asr_common::testing::fileBytes(log).find("not overwritten"), std::string::npos);
  EXPECT_EQ(std::filesystem::file_size(bag), size);
}

}  // namespace
}  // namespace asr_ism

int main(int argc, char** argv) {
  return asr_common::testing::runRostests(argc, argv, "recorder_rostest");
}
