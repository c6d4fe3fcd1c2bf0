// The subcommands of `asr tags`: detect tags in an image, render the simulated camera's image,
// print tags.
#pragma once

#include <string>
#include <vector>

namespace asr_robot_model::tools {

int runTagsDetect(const std::vector<std::string>& arguments);
int runTagsRender(const std::vector<std::string>& arguments);
int runTagsPrint(const std::vector<std::string>& arguments);

/// "0-11", "3", "0,4,7-9" -> the ids in order. Throws UsageError naming --ids otherwise.
std::vector<int> idList(const std::string& text);

}  // namespace asr_robot_model::tools
