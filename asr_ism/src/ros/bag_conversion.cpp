#include "asr_ism/ros/bag_conversion.hpp"

#include <asr_msgs/ObjectEstimateList.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <tf2_msgs/TFMessage.h>
#include <tf2_ros/buffer.h>

#include <vector>

#include "asr_ism/common_types.hpp"
#include "asr_ism/ros/estimate_intake.hpp"
#include "asr_ism/sqlite/demonstration_writer.hpp"

namespace asr_ism::ros_interface {

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

  // Every transform of the bag, kept for its whole length.
  rosbag::View whole(bag);
  const ros::Duration length = whole.getEndTime() - whole.getBeginTime();
  tf2_ros::Buffer buffer(length + ros::Duration(3600));
  for (const rosbag::MessageInstance& message :
       rosbag::View(bag, rosbag::TopicQuery(std::vector<std::string>{"/tf", "/tf_static"}))) {
    if (const auto transforms = message.instantiate<tf2_msgs::TFMessage>()) {
      const bool is_static = message.getTopic() == "/tf_static";
      for (const auto& transform : transforms->transforms)
        buffer.setTransform(transform, "bag", is_static);
    }
  }

  EstimateIntake intake(buffer, fixed_frame, ros::Duration(0));
  BagConversion conversion;
  std::vector<Configuration> configurations;
  std::vector<ObjectKey> objects;
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
