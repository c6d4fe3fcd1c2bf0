// Test support for the suite's gtests (needs gtest): the recordings and a skip without them.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "asr_common/recordings.hpp"

#ifndef ASR_RECORDINGS_DIR
#error "ASR_RECORDINGS_DIR must be defined per test target (see the package's CMakeLists.txt)"
#endif

namespace asr_common::testing {

/// The folder of the real recordings: $ASR_RECORDINGS_DIR, else the test target's compiled-in
/// ASR_RECORDINGS_DIR; empty if it does not exist.
inline std::string recordings() {
  return recordingsDirectory(ASR_RECORDINGS_DIR);
}

/// The path of the recording `name` (e.g. "story_1.sqlite") in recordings().
inline std::string recording(const std::string& name) {
  return recordings() + "/" + name;
}

}  // namespace asr_common::testing

/// Skips the current test, saying where the recordings were looked for, if they are absent.
#define REQUIRE_RECORDINGS()                                                       \
  if (::asr_common::testing::recordings().empty())                                 \
  GTEST_SKIP() << "recordings not found (set ASR_RECORDINGS_DIR or place them at " \
               << ASR_RECORDINGS_DIR << ")"
