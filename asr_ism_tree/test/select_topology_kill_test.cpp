// Fault test of `ism select-topology` (ISM_TOOL): the process is killed with SIGKILL at random
// moments (seeded), and afterwards the model file and the topology file must each be the old or
// the new complete version, readable by read-only users, and the topology file never newer than
// the model. The kill moments vary with the machine's speed; what is asserted does not.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <functional>
#include <random>
#include <thread>

#include "asr_common/testing/temp_dir.hpp"
#include "asr_ism/sqlite/demonstration_writer.hpp"
#include "asr_ism/synthetic_demonstration.hpp"
#include "asr_ism_tree/sqlite/model_store.hpp"
#include "asr_ism_tree/topology_file.hpp"
#include "asr_ism_tree/tree_generation.hpp"

#ifndef ISM_TOOL
#error "ISM_TOOL must be the path of the built ism executable (see asr_ism_tree/CMakeLists.txt)"
#endif

extern char** environ;

namespace asr_ism_tree {
namespace {

using asr_common::testing::fileBytes;
using asr_common::testing::TempDir;
using Clock = std::chrono::steady_clock;

// Starts the tool with its output discarded; returns its process id.
pid_t startTool(const std::vector<std::string>& arguments) {
  std::vector<char*> argv;
  std::string tool = ISM_TOOL;
  argv.push_back(tool.data());
  std::vector<std::string> copies = arguments;
  for (std::string& argument : copies)
    argv.push_back(argument.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = -1;
  const int error = posix_spawn(&pid, tool.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  EXPECT_EQ(error, 0) << "cannot start " << tool;
  return error == 0 ? pid : -1;
}

// Kills `pid` with SIGKILL at the first moment `now()` holds (polled without pause), or after
// `limit`, unless the process has exited before. True if it was killed.
bool killWhen(pid_t pid, const std::function<bool()>& now, std::chrono::duration<double> limit) {
  const auto deadline = Clock::now() + limit;
  int status = 0;
  while (Clock::now() < deadline && !now()) {
    if (waitpid(pid, &status, WNOHANG) == pid)
      return false;
  }
  kill(pid, SIGKILL);
  waitpid(pid, &status, 0);
  return WIFSIGNALED(status);
}

std::uintmax_t sizeOrZero(const std::string& path) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  return error ? 0 : size;
}

// What the model file holds: the relations of its tree, or nothing if it has no model.
struct ModelState {
  bool present = false;
  RelationTopology topology;
  std::size_t relative_poses = 0;
};

ModelState readModel(const std::string& path, const std::string& scene) {
  ModelState state;
  if (!std::filesystem::exists(path) || sqlite::listModelScenes(path).empty())
    return state;
  const IsmTree tree = sqlite::loadIsmTree(path, scene);  // validates the whole tree
  state.present = true;
  state.topology = tree.topology;
  state.relative_poses = tree.relativePoseCount();
  return state;
}

TEST(SelectTopologyKill, ModelAndTopologyFileStayConsistentAfterSigkill) {
  TempDir dir("asr_select_topology_kill");
  const std::string demo = dir.file("demo.sqlite");
  const asr_ism::Demonstration demonstration = asr_ism::makeBreakfastDemonstration(5);
  asr_ism::sqlite::appendDemonstration(demo, demonstration);
  const std::string scene = demonstration.scene();
  const std::string model = dir.file("model.sqlite");
  const std::string topology_file = dir.file("topology.txt");
  const std::vector<std::string> arguments = {"select-topology",
                                              "--demo",
                                              demo,
                                              "--scene",
                                              scene,
                                              "--topology-out",
                                              topology_file,
                                              "--model",
                                              model,
                                              "--tests",
                                              "60",
                                              "--max-evaluations",
                                              "12",
                                              "--seed",
                                              "3",
                                              "--threads",
                                              "1"};

  // The new state: one uninterrupted run, timed to spread the kills over a run's length.
  const auto start = Clock::now();
  const pid_t reference = startTool(arguments);
  int status = 0;
  ASSERT_EQ(waitpid(reference, &status, 0), reference);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "the reference run failed";
  const double run_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  const ModelState new_model = readModel(model, scene);
  const std::string new_topology = fileBytes(topology_file);

  // The old state: a model and topology file of another topology, as a previous run leaves them.
  const RelationTopology star = RelationTopology::star(demonstration.objects(), 0);
  const RelationTopology old_topology =
      star == new_model.topology ? RelationTopology::complete(demonstration.objects()) : star;
  ASSERT_FALSE(old_topology == new_model.topology);
  const std::string old_model_file = dir.file("old_model.sqlite");
  const std::string old_topology_file = dir.file("old_topology.txt");
  sqlite::saveIsmTree(old_model_file, generateIsmTree(demonstration, old_topology, {}), "old");
  writeTopologyFile(old_topology_file, old_topology);
  const ModelState old_model = readModel(old_model_file, scene);
  const std::string old_topology_text = fileBytes(old_topology_file);

  // The kill moments: a third anywhere in a run (seeded), a third inside the model's write (as
  // soon as its rollback journal holds data), a third just after the model's commit (when the
  // journal is gone again), where the topology file is about to be written.
  std::mt19937 random(20261125);
  std::uniform_real_distribution<double> anywhere(0.0, 1.2 * run_seconds);
  const std::string journal = model + "-journal";
  const auto hang_guard = std::chrono::duration<double>(60.0 + 10.0 * run_seconds);
  int killed = 0, journals_recovered = 0, both_old = 0, both_new = 0, model_ahead = 0,
      topology_ahead = 0;
  for (int trial = 0; trial < 30; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    std::filesystem::copy_file(old_model_file, model,
                               std::filesystem::copy_options::overwrite_existing);
    std::filesystem::copy_file(old_topology_file, topology_file,
                               std::filesystem::copy_options::overwrite_existing);
    // A journal belongs to the file it was written for, not to the old copy put in its place.
    std::filesystem::remove(journal);
    const pid_t pid = startTool(arguments);
    ASSERT_GT(pid, 0);
    if (trial % 3 == 0) {
      const auto moment = Clock::now() + std::chrono::duration<double>(anywhere(random));
      killed += killWhen(
          pid, [&] { return Clock::now() >= moment; }, hang_guard);
    } else if (trial % 3 == 1) {
      killed += killWhen(
          pid, [&] { return sizeOrZero(journal) > 0; }, hang_guard);
    } else {
      bool seen = false;
      killed += killWhen(
          pid,
          [&] {
            const bool exists = std::filesystem::exists(journal);
            seen = seen || exists;
            return seen && !exists;
          },
          hang_guard);
    }
    const bool journal_left = std::filesystem::exists(model + "-journal");

    // Read-only users recover the model (a hot journal is rolled back); it is old or new. A
    // journal killed before it held anything is not hot: SQLite ignores it and it stays.
    const ModelState after = readModel(model, scene);
    journals_recovered += journal_left && !std::filesystem::exists(model + "-journal");
    ASSERT_TRUE(after.present);
    const bool model_new =
        after.topology == new_model.topology && after.relative_poses == new_model.relative_poses;
    const bool model_old =
        after.topology == old_model.topology && after.relative_poses == old_model.relative_poses;
    EXPECT_TRUE(model_new || model_old);
    const std::string topology_text = fileBytes(topology_file);
    const bool topology_new = topology_text == new_topology;
    EXPECT_TRUE(topology_new || topology_text == old_topology_text);
    // The topology file is written only after its model is committed.
    EXPECT_FALSE(topology_new && !model_new);
    both_old += model_old && !topology_new;
    both_new += model_new && topology_new;
    model_ahead += model_new && !topology_new;
    topology_ahead += topology_new && !model_new;
  }
  std::printf(
      "select-topology killed %d of 30 times (run %.2f s): %d both old, %d both new, %d model new "
      "with the old topology file, %d topology file ahead; %d hot journals rolled back\n",
      killed, run_seconds, both_old, both_new, model_ahead, topology_ahead, journals_recovered);
  EXPECT_GT(killed, 0) << "no run was interrupted: the test proved nothing";
}

}  // namespace
}  // namespace asr_ism_tree
