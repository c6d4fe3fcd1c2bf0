#include "asr_robot_model/shipped_files.hpp"

#include <filesystem>

namespace asr_robot_model {

std::string shippedFile(const std::string& relative) {
  const std::filesystem::path source = std::filesystem::path(ASR_ROBOT_MODEL_SOURCE_DIR) / relative;
  const std::filesystem::path installed =
      std::filesystem::path(ASR_ROBOT_MODEL_SHARE_DIR) / relative;
  std::error_code error;
  if (!std::filesystem::exists(source, error) && std::filesystem::exists(installed, error))
    return installed.string();
  return source.string();
}

}  // namespace asr_robot_model
