// SQLite files after a writer was killed: the rollback journal it leaves makes a read-only
// connection fail; Database rolls it back and reads the last committed state.

#include "asr_ism/sqlite/sqlite_database.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

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

TEST(SqliteDatabase, ANonDatabaseIsNamedAsSuch) {
  TempDir dir("asr_sqlite_database");
  const std::string path = dir.write("text.sqlite", "this is not a database, just some text\n");
  const std::string message =
      asr_common::testing::inputErrorOf([&] { Database(path, Database::Mode::kReadOnly); });
  EXPECT_NE(message.find(path + ": not an SQLite database"), std::string::npos) << message;
}

}  // namespace
}  // namespace asr_ism::sqlite
