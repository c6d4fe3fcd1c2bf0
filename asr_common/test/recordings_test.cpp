#include "asr_common/recordings.hpp"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <optional>
#include <string>

#include "asr_common/testing/temp_dir.hpp"

namespace asr_common {
namespace {

// Sets $ASR_RECORDINGS_DIR (or unsets it) for the life of the object, then restores it.
class RecordingsVariable {
 public:
  explicit RecordingsVariable(const std::optional<std::string>& value) {
    if (const char* before = std::getenv("ASR_RECORDINGS_DIR"))
      before_ = before;
    if (value)
      ::setenv("ASR_RECORDINGS_DIR", value->c_str(), 1);
    else
      ::unsetenv("ASR_RECORDINGS_DIR");
  }
  ~RecordingsVariable() {
    if (before_)
      ::setenv("ASR_RECORDINGS_DIR", before_->c_str(), 1);
    else
      ::unsetenv("ASR_RECORDINGS_DIR");
  }

 private:
  std::optional<std::string> before_;
};

TEST(Recordings, AGivenFolderComesFirstThenTheVariableThenTheDefault) {
  const RecordingsVariable variable(std::string("/from/variable"));
  EXPECT_EQ(recordingsLocation("/compiled", "/given"), "/given");
  EXPECT_EQ(recordingsLocation("/compiled"), "/from/variable");
  const RecordingsVariable unset(std::nullopt);
  EXPECT_EQ(recordingsLocation("/compiled"), "/compiled");
}

TEST(Recordings, OnlyAnExistingFolderIsTheRecordingsDirectory) {
  const RecordingsVariable unset(std::nullopt);
  testing::TempDir dir("asr_recordings");
  EXPECT_EQ(recordingsDirectory("/compiled", dir.path()), dir.path());
  EXPECT_EQ(recordingsDirectory(dir.file("missing")), "");
  // A file is not a folder of recordings.
  EXPECT_EQ(recordingsDirectory(dir.write("story_1.sqlite", "")), "");
}

}  // namespace
}  // namespace asr_common
