// SQLite files after a writer was killed: the rollback journal it leaves makes a read-only
// connection fail; Database rolls it back and reads the last committed state.

#include "asr_ism/sqlite/sqlite_database.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <sys/stat.h>

#include <csignal>
#include <filesystem>

#include "asr_common/testing/input_error_of.hpp"
#include "asr_common/testing/temp_dir.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"
#include "asr_ism/sqlite/demonstration_writer.hpp"
#include "asr_ism/synthetic_demonstration.hpp"

namespace asr_ism::sqlite {
namespace {

using asr_common::testing::TempDir;

// In a child process: opens `path`, changes every pose inside a transaction with a cache too
// small to hold the change (so pages reach the file before the commit), and dies by SIGKILL
// before committing, as a process killed while saving does.
void killWriterInsideATransaction(const std::string& path) {
  const pid_t child = fork();
  if (child == 0) {
    Database db(path, Database::Mode::kReadWriteCreate);
    db.execute("PRAGMA cache_size = 2");
    db.execute("BEGIN IMMEDIATE");
    db.execute("UPDATE recorded_poses SET px = px + 1000000");
    db.execute(
        "INSERT INTO recorded_poses SELECT NULL, objectId, setId, px, py, pz, qw, qx, qy, "
        "qz FROM recorded_poses");
    raise(SIGKILL);
  }
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
}

TEST(SqliteDatabase, AReaderRollsBackTheJournalOfAKilledWriter) {
  TempDir dir("asr_sqlite_database");
  const std::string path = dir.file("demo.sqlite");
  const Demonstration written = makeBreakfastDemonstration(4);
  appendDemonstration(path, written);
  killWriterInsideATransaction(path);
  ASSERT_TRUE(std::filesystem::exists(path + "-journal")) << "the writer left no journal";
  {
    // What the issue saw: plain SQLite, read-only, fails on the hot journal.
    sqlite3* raw = nullptr;
    sqlite3_open_v2(path.c_str(), &raw, SQLITE_OPEN_READONLY, nullptr);
    EXPECT_NE(sqlite3_exec(raw, "SELECT count(*) FROM sqlite_master", nullptr, nullptr, nullptr),
              SQLITE_OK);
    sqlite3_close(raw);
  }
  // A read-only user of the suite reads the last committed state and leaves no journal.
  const Demonstration read = readDemonstration(path, "breakfast");
  EXPECT_FALSE(std::filesystem::exists(path + "-journal"));
  ASSERT_EQ(read.stepCount(), written.stepCount());
  for (std::size_t step = 0; step < read.stepCount(); ++step) {
    for (std::size_t object = 0; object < read.objectCount(); ++object) {
      ASSERT_TRUE(read.pose(step, object).has_value());
      EXPECT_TRUE(
          approximatelyEqual(*read.pose(step, object), *written.pose(step, object), 1e-12, 1e-12));
    }
  }
}

// The InputError message of a read-only Database(path) opened by a user who may not write the
// file or its folder: as root, in a child process that drops to user nobody; otherwise with the
// file and folder made read-only.
std::string messageOfReaderWhoCannotWrite(const std::string& path, const std::string& folder) {
  int channel[2];
  if (pipe(channel) != 0)
    return "no pipe";
  const pid_t child = fork();
  if (child == 0) {
    close(channel[0]);
    if (geteuid() == 0) {
      if (setgid(65534) != 0 || setuid(65534) != 0)
        _exit(3);
    } else {
      chmod(path.c_str(), 0444);
      chmod(folder.c_str(), 0555);
    }
    std::string message = "no error";
    try {
      Database db(path, Database::Mode::kReadOnly);
    } catch (const InputError& error) {
      message = error.what();
    }
    if (write(channel[1], message.data(), message.size()) < 0)
      _exit(4);
    _exit(0);
  }
  close(channel[1]);
  std::string message;
  char buffer[512];
  for (ssize_t n; (n = read(channel[0], buffer, sizeof buffer)) > 0;)
    message.append(buffer, static_cast<std::size_t>(n));
  close(channel[0]);
  waitpid(child, nullptr, 0);
  chmod(folder.c_str(), 0755);
  chmod(path.c_str(), 0644);
  return message;
}

TEST(SqliteDatabase, AReaderWhoMayNotRollBackSaysWhatToDo) {
  TempDir dir("asr_sqlite_database");
  const std::string path = dir.file("demo.sqlite");
  appendDemonstration(path, makeBreakfastDemonstration(4));
  killWriterInsideATransaction(path);
  ASSERT_TRUE(std::filesystem::exists(path + "-journal"));
  const std::string message = messageOfReaderWhoCannotWrite(path, dir.path());
  EXPECT_NE(message.find(path + ": holds an unfinished write"), std::string::npos) << message;
  EXPECT_NE(message.find(path + "-journal"), std::string::npos) << message;
  EXPECT_NE(message.find("Keep the journal"), std::string::npos) << message;
  // The journal is still there for a user who may write, and that user recovers the file.
  ASSERT_TRUE(std::filesystem::exists(path + "-journal"));
  EXPECT_EQ(readDemonstration(path, "breakfast").stepCount(), 60u);
}

TEST(SqliteDatabase, ANonDatabaseIsNamedAsSuch) {
  TempDir dir("asr_sqlite_database");
  const std::string path = dir.write("text.sqlite", "this is not a database, just some text\n");
  const std::string message =
      asr_common::testing::inputErrorOf([&] { Database(path, Database::Mode::kReadOnly); });
  EXPECT_NE(message.find(path + ": not an SQLite database"), std::string::npos) << message;
}

}  // namespace
}  // namespace asr_ism::sqlite
