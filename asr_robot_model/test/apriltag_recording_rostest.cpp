// A demonstration recorded from the AprilTag chain (rostest, robot_sim.launch detector:=apriltag
// with the shipped kitchen, and asr_ism's recorder started as a user does with rosrun): the
// recorder turns the detector's camera-frame estimates into map poses and writes them into a
// demonstration file that already holds the user's earlier recordings; the written sets hold the
// objects at their true places, and every earlier scene reads back exactly as before.
#include <asr_msgs/ObjectEstimateList.h>
#include <asr_msgs/RecordConfiguration.h>
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <filesystem>

#include "asr_common/child_process.hpp"
#include "asr_common/testing/recordings_skip.hpp"
#include "asr_common/testing/rostest_support.hpp"
#include "asr_common/testing/temp_dir.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"
#include "simulation_probe.hpp"

namespace asr_robot_model {
namespace {

using asr_common::testing::waitFor;

/// Every pose of every step equal (the same rows read back).
void expectSameDemonstration(const asr_ism::Demonstration& a, const asr_ism::Demonstration& b) {
  ASSERT_EQ(a.stepCount(), b.stepCount()) << a.scene();
  ASSERT_EQ(a.objects(), b.objects()) << a.scene();
  for (std::size_t step = 0; step < a.stepCount(); ++step)
    for (std::size_t object = 0; object < a.objectCount(); ++object) {
      const auto& pose_a = a.pose(step, object);
      const auto& pose_b = b.pose(step, object);
      ASSERT_EQ(pose_a.has_value(), pose_b.has_value()) << a.scene() << " set " << step;
      if (pose_a) {
        EXPECT_EQ(pose_a->position, pose_b->position) << a.scene() << " set " << step;
        EXPECT_EQ(pose_a->orientation.coeffs(), pose_b->orientation.coeffs());
      }
    }
}

TEST(ApriltagRecording, TheRecorderWritesTheDetectedObjectsAndKeepsEarlierRecordings) {
  REQUIRE_RECORDINGS();
  ros::NodeHandle handle;
  testing::SimulationProbe probe;
  const testing::Kitchen kitchen;
  asr_common::testing::TempDir dir("asr_apriltag_recording");
  // The user's earlier demonstrations: the file the new recording goes into.
  const std::string source = asr_common::testing::recording("story_2.sqlite");
  const std::string file = dir.file("demonstrations.sqlite");
  std::filesystem::copy_file(source, file);
  const std::vector<std::string> earlier_scenes = asr_ism::sqlite::listRecordedScenes(source);

  bool cup_seen = false;
  ros::Subscriber objects = handle.subscribe<asr_msgs::ObjectEstimateList>(
      "objects", 10, [&](const asr_msgs::ObjectEstimateListConstPtr& list) {
        for (const auto& estimate : list->objects)
          cup_seen = cup_seen || estimate.type == "Cup";
      });
  ASSERT_TRUE(probe.waitForDriver(60)) << "robot_driver did not start";
  ASSERT_TRUE(waitFor([&] { return cup_seen; }, 60)) << "the detector never reported the cup";

  // Service mode: one set per call, of the latest estimates (which never expire here).
  asr_common::ChildProcess recorder(
      "/usr/bin/rosrun",
      {"asr_ism", "recorder", "__name:=recorder", "_demonstration_file:=" + file,
       "_scene:=kitchen_tags", "_mode:=service", "_fixed_frame:=map", "_estimate_timeout:=0"},
      dir.file("recorder.log"), dir.file("recorder.log"));
  ros::ServiceClient record =
      handle.serviceClient<asr_msgs::RecordConfiguration>("record_configuration");
  ASSERT_TRUE(record.waitForExistence(ros::Duration(30)))
      << asr_common::testing::fileBytes(dir.file("recorder.log"));
  asr_msgs::RecordConfiguration call;
  for (int set = 0; set < 2; ++set) {
    // Until the recorder has estimates (they arrive with the camera's frames, 5 per second);
    // waitFor asks once more at the end, so the call is made only until one succeeds.
    bool recorded = false;
    ASSERT_TRUE(waitFor(
        [&] { return recorded = recorded || (record.call(call) && call.response.success); }, 30))
        << call.response.message << "\n"
        << asr_common::testing::fileBytes(dir.file("recorder.log"));
    EXPECT_GE(call.response.object_count, 1u);
  }
  recorder.stop(std::chrono::seconds(10));

  const asr_ism::Demonstration recorded = asr_ism::sqlite::readDemonstration(file, "kitchen_tags");
  ASSERT_EQ(recorded.stepCount(), 2u);
  bool cup_recorded = false;
  for (std::size_t index = 0; index < recorded.objectCount(); ++index) {
    const asr_common::ObjectKey& key = recorded.objects()[index];
    const auto truth = std::find_if(kitchen.world.objects.begin(), kitchen.world.objects.end(),
                                    [&](const WorldObject& o) { return o.key == key; });
    ASSERT_NE(truth, kitchen.world.objects.end()) << key.toString() << " is not in the kitchen";
    cup_recorded = cup_recorded || key.type == "Cup";
    for (std::size_t step = 0; step < recorded.stepCount(); ++step) {
      const auto& pose = recorded.pose(step, index);
      if (!pose)
        continue;
      EXPECT_LE((pose->position - truth->box.pose.position).norm(), 0.03) << key.toString();
      EXPECT_LE(asr_common::angleBetween(pose->orientation, truth->box.pose.orientation), 0.1)
          << key.toString();
    }
  }
  EXPECT_TRUE(cup_recorded);

  // Nothing the user recorded before is changed.
  std::vector<std::string> scenes = asr_ism::sqlite::listRecordedScenes(file);
  ASSERT_EQ(scenes.size(), earlier_scenes.size() + 1);
  for (const std::string& scene : earlier_scenes)
    expectSameDemonstration(asr_ism::sqlite::readDemonstration(file, scene),
                            asr_ism::sqlite::readDemonstration(source, scene));
}

}  // namespace
}  // namespace asr_robot_model

int main(int argc, char** argv) {
  return asr_common::testing::runRostests(argc, argv, "apriltag_recording_rostest");
}
