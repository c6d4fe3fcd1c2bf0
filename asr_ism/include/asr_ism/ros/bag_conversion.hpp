#pragma once

#include <cstddef>
#include <map>
#include <string>

namespace asr_ism::ros_interface {

/// What a rosbag conversion did.
struct BagConversion {
  std::size_t messages = 0;        // ObjectEstimateList messages read on the topic
  std::size_t configurations = 0;  // sets written (messages with at least one valid estimate)
  std::size_t estimates = 0;       // estimates written
  std::size_t rejected = 0;        // estimates skipped (invalid, or no transform in the bag)
  std::map<std::string, std::size_t> rejected_by_reason;
};

/// Converts the asr_msgs/ObjectEstimateList messages on `topic` of the rosbag `bag_path` into
/// recorded sets of `scene` in the demonstration file `demonstration_path` (original ASR schema;
/// created, or appended to, never truncated), one set per message, all in one transaction.
/// Estimates in other frames are transformed into `fixed_frame` with the transforms the bag
/// holds on /tf and /tf_static, at each estimate's time stamp; invalid estimates (NaN, zero
/// quaternion, empty type) and ones without a transform are skipped and counted. Throws
/// InputError naming the bag, topic or file if the bag cannot be read, the topic has no such
/// messages, or nothing valid remains.
BagConversion convertBagToDemonstration(const std::string& bag_path, const std::string& topic,
                                        const std::string& demonstration_path,
                                        const std::string& scene, const std::string& fixed_frame);

}  // namespace asr_ism::ros_interface
