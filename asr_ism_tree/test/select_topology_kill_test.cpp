// Fault test of `ism select-topology` (ISM_TOOL): the process is killed with SIGKILL at random
// moments (seeded), and afterwards the model file and the topology file must each be the old or
// the new complete version, readable by read-only users, and the topology file never newer than
// the model. The kill moments vary with the machine's speed; what is asserted does not.

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <random>

#include "asr_common/child_process.hpp"
#include "asr_common/testing/temp_dir.hpp"
#include "asr_ism/sqlite/demonstration_writer.hpp"
#include "asr_ism/synthetic_demonstration.hpp"
#include "asr_ism_tree/sqlite/model_store.hpp"
#include "asr_ism_tree/topology_file.hpp"
#include "asr_ism_tree/tree_generation.hpp"

#ifndef ISM_TOOL
#error "ISM_TOOL must be the path of the built ism executable (see asr_ism_tree/CMakeLists.txt)"
#endif

namespace asr_ism_tree {
namespace {

using asr_common::testing::fileBytes;
using asr_common::testing::TempDir;
using Clock = std::chrono::steady_clock;

// Kills `tool` with SIGKILL at the first moment `now()` holds (polled without pause), or after
// `limit`, unless it has exited before. True if it was killed.
bool killWhen(asr_common::ChildProcess& tool, const std::function<bool()>& now,
              std::chrono::duration<double> limit) {
  const auto deadline = Clock::now() + limit;
  while (Clock::now() < deadline && !now() && tool.running()) {
  }
  return tool.killNow();
}

asr_common::ChildProcess startTool(const std::vector<std::string>& arguments) {
  return asr_common::ChildProcess(ISM_TOOL, arguments, "/dev/null", "/dev/null");
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

// The files of one scenario: a demonstration, the files select-topology writes, and the old
// and new states of both (old: a previous run's other topology; new: an uninterrupted run).
struct Scenario {
  TempDir dir{"asr_select_topology_kill"};
  std::string scene, model, topology_file;
  std::vector<std::string> arguments;
  double run_seconds = 0.0;
  ModelState new_model, old_model;
  std::string new_topology, old_topology;
  std::string old_model_file, old_topology_file;
};

std::vector<std::string> selectTopologyArguments(const Scenario& scenario,
                                                 const std::string& demo) {
  return {"select-topology",
          "--demo",
          demo,
          "--scene",
          scenario.scene,
          "--topology-out",
          scenario.topology_file,
          "--model",
          scenario.model,
          "--tests",
          "60",
          "--max-evaluations",
          "12",
          "--seed",
          "3",
          "--threads",
          "1"};
}

// The new state from one uninterrupted run, timed to spread the kills over a run's length.
void recordNewState(Scenario& scenario) {
  const auto start = Clock::now();
  ASSERT_EQ(startTool(scenario.arguments).wait(), 0) << "the reference run failed";
  scenario.run_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  scenario.new_model = readModel(scenario.model, scenario.scene);
  scenario.new_topology = fileBytes(scenario.topology_file);
}

// The old state: a model and topology file of another topology, as a previous run leaves them.
void recordOldState(Scenario& scenario, const asr_ism::Demonstration& demonstration) {
  const RelationTopology star = RelationTopology::star(demonstration.objects(), 0);
  const RelationTopology old_topology = star == scenario.new_model.topology
                                            ? RelationTopology::complete(demonstration.objects())
                                            : star;
  ASSERT_FALSE(old_topology == scenario.new_model.topology);
  scenario.old_model_file = scenario.dir.file("old_model.sqlite");
  scenario.old_topology_file = scenario.dir.file("old_topology.txt");
  sqlite::saveIsmTree(scenario.old_model_file, generateIsmTree(demonstration, old_topology, {}),
                      "old");
  writeTopologyFile(scenario.old_topology_file, old_topology);
  scenario.old_model = readModel(scenario.old_model_file, scenario.scene);
  scenario.old_topology = fileBytes(scenario.old_topology_file);
}

void prepare(Scenario& scenario) {
  const std::string demo = scenario.dir.file("demo.sqlite");
  const asr_ism::Demonstration demonstration = asr_ism::makeBreakfastDemonstration(5);
  asr_ism::sqlite::appendDemonstration(demo, demonstration);
  scenario.scene = demonstration.scene();
  scenario.model = scenario.dir.file("model.sqlite");
  scenario.topology_file = scenario.dir.file("topology.txt");
  scenario.arguments = selectTopologyArguments(scenario, demo);
  ASSERT_NO_FATAL_FAILURE(recordNewState(scenario));
  ASSERT_NO_FATAL_FAILURE(recordOldState(scenario, demonstration));
}

// Puts the old state in place; a journal belongs to the file it was written for, not to the
// old copy put in its place.
void restoreOldState(const Scenario& scenario) {
  const auto overwrite = std::filesystem::copy_options::overwrite_existing;
  std::filesystem::copy_file(scenario.old_model_file, scenario.model, overwrite);
  std::filesystem::copy_file(scenario.old_topology_file, scenario.topology_file, overwrite);
  std::filesystem::remove(scenario.model + "-journal");
}

// Runs the tool and kills it: a third of the trials anywhere in a run (seeded), a third inside
// the model's write (as soon as its rollback journal holds data), a third just after the
// model's commit (when the journal is gone again), where the topology file is about to be
// written. True if it was killed.
bool runAndKill(const Scenario& scenario, int trial, double moment_seconds) {
  const std::string journal = scenario.model + "-journal";
  const auto hang_guard = std::chrono::duration<double>(60.0 + 10.0 * scenario.run_seconds);
  asr_common::ChildProcess tool = startTool(scenario.arguments);
  if (trial % 3 == 0) {
    const auto moment = Clock::now() + std::chrono::duration<double>(moment_seconds);
    return killWhen(
        tool, [&] { return Clock::now() >= moment; }, hang_guard);
  }
  if (trial % 3 == 1)
    return killWhen(
        tool, [&] { return sizeOrZero(journal) > 0; }, hang_guard);
  bool seen = false;
  return killWhen(
      tool,
      [&] {
        const bool exists = std::filesystem::exists(journal);
        seen = seen || exists;
        return seen && !exists;
      },
      hang_guard);
}

struct Tally {
  int killed = 0, journals_recovered = 0, both_old = 0, both_new = 0, model_ahead = 0,
      topology_ahead = 0;
};

// Read-only users recover the model (a hot journal is rolled back); model and topology file are
// each old or new, and the topology file is never newer than the model. A journal killed before
// it held anything is not hot: SQLite ignores it and it stays.
void checkAfterKill(const Scenario& scenario, Tally& tally) {
  const std::string journal = scenario.model + "-journal";
  const bool journal_left = std::filesystem::exists(journal);
  const ModelState after = readModel(scenario.model, scenario.scene);
  tally.journals_recovered += journal_left && !std::filesystem::exists(journal);
  ASSERT_TRUE(after.present);
  const bool model_new = after.topology == scenario.new_model.topology &&
                         after.relative_poses == scenario.new_model.relative_poses;
  const bool model_old = after.topology == scenario.old_model.topology &&
                         after.relative_poses == scenario.old_model.relative_poses;
  EXPECT_TRUE(model_new || model_old);
  const std::string topology_text = fileBytes(scenario.topology_file);
  const bool topology_new = topology_text == scenario.new_topology;
  EXPECT_TRUE(topology_new || topology_text == scenario.old_topology);
  EXPECT_FALSE(topology_new && !model_new) << "the topology file was written before its model";
  tally.both_old += model_old && !topology_new;
  tally.both_new += model_new && topology_new;
  tally.model_ahead += model_new && !topology_new;
  tally.topology_ahead += topology_new && !model_new;
}

TEST(SelectTopologyKill, ModelAndTopologyFileStayConsistentAfterSigkill) {
  Scenario scenario;
  ASSERT_NO_FATAL_FAILURE(prepare(scenario));
  std::mt19937 random(20261125);
  std::uniform_real_distribution<double> anywhere(0.0, 1.2 * scenario.run_seconds);
  Tally tally;
  for (int trial = 0; trial < 30; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    restoreOldState(scenario);
    tally.killed += runAndKill(scenario, trial, anywhere(random));
    ASSERT_NO_FATAL_FAILURE(checkAfterKill(scenario, tally));
  }
  std::printf(
      "select-topology killed %d of 30 times (run %.2f s): %d both old, %d both new, %d model new "
      "with the old topology file, %d topology file ahead; %d hot journals rolled back\n",
      tally.killed, scenario.run_seconds, tally.both_old, tally.both_new, tally.model_ahead,
      tally.topology_ahead, tally.journals_recovered);
  EXPECT_GT(tally.killed, 0) << "no run was interrupted: the test proved nothing";
}

}  // namespace
}  // namespace asr_ism_tree
