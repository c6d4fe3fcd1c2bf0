#include "asr_common/recordings.hpp"

#include <sys/stat.h>

#include <cstdlib>

namespace asr_common {

std::string recordingsLocation(const std::string& compiled_default, const std::string& given) {
  if (!given.empty())
    return given;
  const char* from_environment = std::getenv("ASR_RECORDINGS_DIR");
  return from_environment != nullptr ? from_environment : compiled_default;
}

std::string recordingsDirectory(const std::string& compiled_default, const std::string& given) {
  const std::string location = recordingsLocation(compiled_default, given);
  return isDirectory(location) ? location : std::string();
}

bool isDirectory(const std::string& path) {
  struct stat info;
  return stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode);
}

}  // namespace asr_common
