#include "asr_ism/ros/bag_conversion.hpp"

#include <asr_msgs/ObjectEstimateList.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <tf2_msgs/TFMessage.h>
#include <tf2_ros/buffer.h>

#include <algorithm>
#include <vector>

#include "asr_ism/common_types.hpp"
#include "asr_ism/ros/estimate_intake.hpp"
#include "asr_ism/sqlite/demonstration_writer.hpp"

namespace asr_ism::ros_interface {

namespace {

// Every transform of the bag, kept for its whole length.
void loadTransforms(rosbag::Bag& bag, tf2_ros::Buffer& buffer) {
  for (const rosbag::MessageInstance& message :
       rosbag::View(bag, rosbag::TopicQuery(std::vector<std::string>{"/tf", "/tf_static"}))) {
    if (const auto transforms = message.instantiate<tf2_msgs::TFMessage>()) {
      const bool is_static = message.getTopic() == "/tf_static";
      for (const auto& transform : transforms->transforms)
        buffer.setTransform(transform, "bag", is_static);
    }
  }
}

// The accepted estimates of every message on `topic`, one configuration per message that has
// any, and the objects in order of first appearance; counts in `conversion`.
std::vector<Configuration> readConfigurations(rosbag::Bag& bag, const std::string& bag_path,
                                              const std::string& topic, EstimateIntake& intake,
                                              std::vector<ObjectKey>& objects,
                                              BagConversion& conversion) {
  std::vector<Configuration> configurations;
  for (const rosbag::MessageInstance& message : rosbag::View(bag, rosbag::TopicQuery(topic))) {
    const auto list = message.instantiate<asr_msgs::ObjectEstimateList>();
    if (!list)
      throw InputError(bag_path + ": topic " + topic + " carries " + message.getDataType() +
                       ", not asr_msgs/ObjectEstimateList");
    ++conversion.messages;
    Configuration configuration;
    for (const asr_msgs::ObjectEstimate& estimate : list->objects) {
      if (auto accepted = intake.accept(estimate)) {
        if (std::find(objects.begin(), objects.end(), accepted->key) == objects.end())
          objects.push_back(accepted->key);
        configuration.push_back(*accepted);
      }
    }
    if (!configuration.empty())
      configurations.push_back(std::move(configuration));
  }
  return configurations;
}

}  // namespace

BagConversion convertBagToDemonstration(const std::string& bag_path, const std::string& topic,
                                        const std::string& demonstration_path,
                                        const std::string& scene, const std::string& fixed_frame) {
  if (!ros::Time::isValid())
    ros::Time::init();  // a tool without a node: message times come from the bag
  rosbag::Bag bag;
  try {
    bag.open(bag_path, rosbag::bagmode::Read);
  } catch (const rosbag::BagException& error) {
    throw InputError(bag_path + ": cannot read the bag: " + error.what());
  }
  rosbag::View whole(bag);
  tf2_ros::Buffer buffer(whole.getEndTime() - whole.getBeginTime() + ros::Duration(3600));
  loadTransforms(bag, buffer);

  EstimateIntake intake(buffer, fixed_frame, ros::Duration(0));
  BagConversion conversion;
  std::vector<ObjectKey> objects;
  const std::vector<Configuration> configurations =
      readConfigurations(bag, bag_path, topic, intake, objects, conversion);
  conversion.rejected = intake.rejectedCount();
  conversion.rejected_by_reason = intake.rejectedByReason();
  if (conversion.messages == 0)
    throw InputError(bag_path + ": no message on topic " + topic);
  if (configurations.empty())
    throw InputError(bag_path + ": no valid object estimate on topic " + topic + " (" +
                     std::to_string(conversion.rejected) + " rejected)");

  Demonstration demonstration(scene, objects);
  for (const Configuration& configuration : configurations) {
    const std::size_t step = demonstration.addStep();
    for (const ObjectEstimate& estimate : configuration) {
      demonstration.setPose(step, static_cast<std::size_t>(demonstration.indexOf(estimate.key)),
                            estimate.pose);
      ++conversion.estimates;
    }
  }
  sqlite::appendDemonstration(demonstration_path, demonstration);
  conversion.configurations = configurations.size();
  return conversion;
}

}  // namespace asr_ism::ros_interface
