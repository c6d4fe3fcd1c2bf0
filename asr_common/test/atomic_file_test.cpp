#include "asr_common/atomic_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "asr_common/testing/input_error_of.hpp"
#include "asr_common/testing/temp_dir.hpp"

namespace asr_common {
namespace {

namespace fs = std::filesystem;
using testing::fileBytes;
using testing::inputErrorOf;
using testing::TempDir;

TEST(AtomicFile, WritesNewFilesAndReplacesOldOnesWhole) {
  TempDir dir("asr_atomic");
  const std::string path = dir.file("out.txt");
  writeFileAtomically(path, "first\n");
  EXPECT_EQ(fileBytes(path), "first\n");
  writeFileAtomically(path, "");
  EXPECT_EQ(fileBytes(path), "");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.txt"}) << "no temporary file left";
}

// Property: any bytes (NUL, line breaks, high bytes; up to 64 KiB) read back exactly.
TEST(AtomicFile, AnyContentReadsBackExactly) {
  TempDir dir("asr_atomic");
  std::mt19937 random(11);
  for (int round = 0; round < 40; ++round) {
    std::string content(random() % 65536, '\0');
    for (char& byte : content)
      byte = static_cast<char>(random() % 256);
    writeFileAtomically(dir.file("bytes.bin"), content);
    ASSERT_EQ(fileBytes(dir.file("bytes.bin")), content) << "round " << round;
  }
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"bytes.bin"});
}

TEST(AtomicFile, AReplacedFileKeepsItsPermissions) {
  TempDir dir("asr_atomic");
  const std::string path = dir.write("kept.txt", "old\n");
  const fs::perms perms = fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read;
  fs::permissions(path, perms);
  writeFileAtomically(path, "new\n");
  EXPECT_EQ(fs::status(path).permissions(), perms);
}

TEST(AtomicFile, AMissingFolderIsNamedAndNothingIsCreated) {
  TempDir dir("asr_atomic");
  const std::string path = dir.file("missing/out.txt");
  const std::string message = inputErrorOf([&] { writeFileAtomically(path, "x"); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_TRUE(dir.entries().empty());
}

TEST(AtomicFile, ATargetThatCannotBeReplacedIsLeftAsItWas) {
  TempDir dir("asr_atomic");
  // A non-empty folder under the target name: the rename fails after the content is written.
  const std::string path = dir.file("out.txt");
  fs::create_directories(path + "/inside");
  const std::string message = inputErrorOf([&] { writeFileAtomically(path, "x"); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_TRUE(fs::is_directory(path + "/inside"));
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.txt"}) << "temporary file removed";
}

}  // namespace
}  // namespace asr_common
