#pragma once

#include <sys/stat.h>

#include <cstdlib>
#include <string>

namespace asr_common {

/// The folder of the real ASR recordings that tests and benchmarks read: $ASR_RECORDINGS_DIR if
/// set, otherwise `compiled_default` (../shared/data/asr_recordings beside the repository).
/// Returns an empty string if the folder does not exist, so callers can skip with a message.
inline std::string recordingsDirectory(const std::string& compiled_default) {
  const char* from_environment = std::getenv("ASR_RECORDINGS_DIR");
  const std::string directory = from_environment != nullptr ? from_environment : compiled_default;
  struct stat info;
  return stat(directory.c_str(), &info) == 0 && S_ISDIR(info.st_mode) ? directory : std::string();
}

}  // namespace asr_common
