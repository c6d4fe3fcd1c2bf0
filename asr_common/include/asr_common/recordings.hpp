#pragma once

#include <string>

namespace asr_common {

/// Where the real ASR recordings (../shared/data/asr_recordings beside the repository) are
/// looked for, the one rule for tests, benchmarks and tools: `given` if not empty (a
/// --recordings option), else $ASR_RECORDINGS_DIR if set, else `compiled_default`.
std::string recordingsLocation(const std::string& compiled_default, const std::string& given = "");

/// recordingsLocation if it is a folder; an empty string otherwise, so callers can skip with a
/// message.
std::string recordingsDirectory(const std::string& compiled_default, const std::string& given = "");

bool isDirectory(const std::string& path);

}  // namespace asr_common
