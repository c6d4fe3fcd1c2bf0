#include "asr_common/child_process.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <stdexcept>
#include <string>

#include "asr_common/testing/temp_dir.hpp"

namespace asr_common {
namespace {

using testing::fileBytes;
using testing::TempDir;

TEST(ChildProcess, ExitCodeAndOutputsArriveAsWritten) {
  TempDir dir("asr_child");
  // Arguments pass without a shell: the quote and the space stay in the one argument.
  ChildProcess child("/bin/sh", {"-c", "printf '%s' \"$0\"; echo err >&2; exit 3", "it's a b"},
                     dir.file("out"), dir.file("err"));
  EXPECT_EQ(child.wait(), 3);
  EXPECT_EQ(fileBytes(dir.file("out")), "it's a b");
  EXPECT_EQ(fileBytes(dir.file("err")), "err\n");
}

TEST(ChildProcess, StandardInputIsEmpty) {
  TempDir dir("asr_child");
  ChildProcess child("/bin/cat", {}, dir.file("out"), dir.file("err"));
  EXPECT_EQ(child.waitForExit(std::chrono::seconds(10)), 0);
  EXPECT_EQ(fileBytes(dir.file("out")), "");
}

TEST(ChildProcess, AProgramThatRunsOnIsStoppedAndCollected) {
  ChildProcess child("/bin/sleep", {"60"});
  EXPECT_TRUE(child.running());
  EXPECT_EQ(child.waitForExit(std::chrono::milliseconds(50)), -1);
  child.stop();  // SIGINT ends sleep
  EXPECT_FALSE(child.running());
  EXPECT_EQ(child.wait(), -1) << "ended by a signal";
}

TEST(ChildProcess, AMissingProgramIsNamed) {
  try {
    ChildProcess child("/nonexistent/node", {});
    // posix_spawn may report the failed exec as exit code 127 instead of an error.
    EXPECT_EQ(child.wait(), 127);
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent/node"), std::string::npos);
  }
}

}  // namespace
}  // namespace asr_common
