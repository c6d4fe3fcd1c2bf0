// End-to-end tests of the built `ism` tool (ISM_TOOL): learn, info and recognize as a user runs
// them, on the real recordings and on small files written here; exit codes, stdout and stderr.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "asr_common/testing/recordings_skip.hpp"
#include "asr_common/testing/temp_dir.hpp"
#include "asr_common/testing/tool_run.hpp"
#include "asr_ism/configuration_file.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"
#include "asr_ism/sqlite/demonstration_writer.hpp"
#include "asr_ism/sqlite/sqlite_database.hpp"
#include "asr_ism/synthetic_demonstration.hpp"
#include "asr_ism_tree/sqlite/model_store.hpp"

#ifndef ISM_TOOL
#error "ISM_TOOL must be the path of the built ism executable (see asr_ism_tree/CMakeLists.txt)"
#endif

namespace asr_ism_tree {
namespace {

using asr_common::testing::fileBytes;
using asr_common::testing::recording;
using asr_common::testing::TempDir;
using nlohmann::json;

constexpr char kPrefix[] = "asr_ism_tool";

// ---- running the tool ----

using asr_common::testing::describe;
using asr_common::testing::expectInputError;
using asr_common::testing::expectSuccess;
using asr_common::testing::lines;
using asr_common::testing::ToolRun;

ToolRun runIsm(const TempDir& dir, const std::vector<std::string>& arguments) {
  return asr_common::testing::runTool(ISM_TOOL, dir, arguments);
}

// A usage error: exit code 2, one line naming `named`, then the usage text and nothing else.
void expectUsageError(const ToolRun& run, const std::string& named) {
  EXPECT_EQ(run.exit_code, 2) << describe(run);
  EXPECT_TRUE(run.out.empty()) << describe(run);
  ASSERT_GE(run.err.size(), 2u) << describe(run);
  EXPECT_NE(run.err[0].find(named), std::string::npos) << run.err[0];
  EXPECT_EQ(run.err[1].rfind("usage: ism", 0), 0u) << describe(run);
  for (std::size_t i = 2; i < run.err.size(); ++i) {
    EXPECT_TRUE(run.err[i].rfind("commands:", 0) == 0 || run.err[i].rfind("  ", 0) == 0)
        << "not a usage line: " << run.err[i];
  }
}

// ---- JSON output ----

std::set<std::string> keysOf(const json& object) {
  std::set<std::string> keys;
  for (const auto& item : object.items())
    keys.insert(item.key());
  return keys;
}

// Parses `recognize --json` output and checks its shape: exactly the documented keys, every
// number a number, instances sorted by confidence (best first).
json parseRecognition(const ToolRun& run, const std::string& scene) {
  json output;
  try {
    output = json::parse(run.out);
  } catch (const json::parse_error& error) {
    ADD_FAILURE() << "not JSON (" << error.what() << "):\n" << run.out;
    return json();
  }
  using Keys = std::set<std::string>;
  EXPECT_EQ(keysOf(output), (Keys{"scene", "runtime_ms", "instances"}));
  EXPECT_EQ(output.value("scene", ""), scene);
  EXPECT_TRUE(output["runtime_ms"].is_number());
  EXPECT_TRUE(output["instances"].is_array());
  double previous = 2.0;
  for (const json& instance : output["instances"]) {
    EXPECT_EQ(keysOf(instance), (Keys{"confidence", "object_confidence", "ids_ignored",
                                      "search_complete", "pose", "objects", "missing", "isms"}));
    EXPECT_TRUE(instance["confidence"].is_number());
    EXPECT_TRUE(instance["object_confidence"].is_number());
    EXPECT_TRUE(instance["ids_ignored"].is_boolean());
    EXPECT_TRUE(instance["search_complete"].is_boolean());
    const double confidence = instance["confidence"].get<double>();
    EXPECT_LE(confidence, previous) << "instances are sorted by confidence, best first";
    previous = confidence;
    EXPECT_EQ(keysOf(instance["pose"]), (Keys{"position", "orientation"}));
    EXPECT_EQ(keysOf(instance["pose"]["position"]), (Keys{"x", "y", "z"}));
    EXPECT_EQ(keysOf(instance["pose"]["orientation"]), (Keys{"x", "y", "z", "w"}));
    for (const auto& part : {instance["pose"]["position"], instance["pose"]["orientation"]}) {
      for (const auto& value : part)
        EXPECT_TRUE(value.is_number());
    }
    EXPECT_TRUE(instance["objects"].is_array());
    for (const json& object : instance["objects"]) {
      EXPECT_EQ(keysOf(object), (Keys{"type", "id", "similarity", "position_compliance",
                                      "orientation_compliance"}));
      EXPECT_TRUE(object["type"].is_string() && object["id"].is_string());
      EXPECT_TRUE(object["similarity"].is_number());
      EXPECT_TRUE(object["position_compliance"].is_number());
      EXPECT_TRUE(object["orientation_compliance"].is_number());
    }
    EXPECT_TRUE(instance["missing"].is_array());
    for (const json& object : instance["missing"])
      EXPECT_EQ(keysOf(object), (Keys{"type", "id"}));
    EXPECT_TRUE(instance["isms"].is_array());
    EXPECT_FALSE(instance["isms"].empty());
    for (const json& ism : instance["isms"]) {
      EXPECT_EQ(keysOf(ism), (Keys{"name", "objective"}));
      EXPECT_TRUE(ism["name"].is_string() && ism["objective"].is_number());
    }
  }
  return output;
}

double bestConfidence(const json& output) {
  if (!output.contains("instances") || output["instances"].empty())
    return 0.0;
  return output["instances"][0].value("confidence", 0.0);
}

// ---- files the tests write ----

// The objects of `configuration` as a JSON objects file (nlohmann keeps doubles exact).
std::string writeJsonObjects(const TempDir& dir, const std::string& name,
                             const asr_common::Configuration& configuration) {
  json objects = json::array();
  for (const auto& estimate : configuration) {
    const auto& p = estimate.pose.position;
    const auto& q = estimate.pose.orientation;
    objects.push_back(
        {{"type", estimate.key.type},
         {"id", estimate.key.id},
         {"pose",
          {{"position", {{"x", p.x()}, {"y", p.y()}, {"z", p.z()}}},
           {"orientation", {{"x", q.x()}, {"y", q.y()}, {"z", q.z()}, {"w", q.w()}}}}}});
  }
  return dir.write(name, json{{"objects", objects}}.dump(2));
}

// A small demonstration file with two scenes: "table" (4 objects) and "shelf" (3 objects).
std::string writeSmallDemonstration(const TempDir& dir) {
  const std::string path = dir.file("small_demo.sqlite");
  asr_ism::sqlite::appendDemonstration(path,
                                       asr_ism::makeSyntheticDemonstration(4, 12, 7, "table"));
  asr_ism::sqlite::appendDemonstration(path, asr_ism::makeSyntheticDemonstration(3, 8, 8, "shelf"));
  return path;
}

// A file in the original schema whose scene "nothing" has no recorded set.
std::string writeEmptyDemonstration(const TempDir& dir) {
  const std::string path = dir.file("empty_demo.sqlite");
  asr_ism::sqlite::Database db(path, asr_ism::sqlite::Database::Mode::kReadWriteCreate);
  db.execute("CREATE TABLE recorded_patterns (id INTEGER PRIMARY KEY, name TEXT)");
  db.execute("CREATE TABLE recorded_sets (id INTEGER PRIMARY KEY, patternId INTEGER)");
  db.execute(
      "CREATE TABLE recorded_objects (id INTEGER PRIMARY KEY, type TEXT, observedId TEXT, "
      "resourcePath TEXT)");
  db.execute(
      "CREATE TABLE recorded_poses (id INTEGER PRIMARY KEY, objectId INTEGER, setId INTEGER, "
      "px FLOAT, py FLOAT, pz FLOAT, qw FLOAT, qx FLOAT, qy FLOAT, qz FLOAT)");
  db.execute("INSERT INTO recorded_patterns (name) VALUES ('nothing')");
  return path;
}

std::vector<std::string> learnArguments(const std::string& demo, const std::string& scene,
                                        const std::string& topology, const std::string& model) {
  return {"learn", "--demo", demo, "--scene", scene, "--topology", topology, "--model", model};
}

// `info` shows, for the model stored in `model`, its relations, ISMs and levels.
void expectInfoDescribes(const TempDir& dir, const std::string& model, const std::string& scene) {
  const ToolRun info = runIsm(dir, {"info", "--model", model, "--scene", scene});
  expectSuccess(info);
  const IsmTree tree = sqlite::loadIsmTree(model, scene);
  const std::string summary = "scene '" + scene + "': " + std::to_string(tree.objects().size()) +
                              " objects, " + std::to_string(tree.topology.relationCount()) +
                              " relations, " + std::to_string(tree.isms.size()) + " ISMs in " +
                              std::to_string(tree.height()) + " levels";
  EXPECT_EQ(info.out.rfind(summary, 0), 0u) << summary << "\n" << info.out;
  for (std::size_t i = 0; i < tree.isms.size(); ++i) {
    const std::string line =
        "ISM " + tree.isms[i].name + " (level " + std::to_string(tree.level[i]) + ",";
    EXPECT_NE(info.out.find(line), std::string::npos) << line << "\n" << info.out;
  }
}

// Runs the tool in a fresh folder on one demonstration file, demo_.
class IsmToolTest : public ::testing::Test {
 protected:
  IsmToolTest() : dir_(kPrefix) {}

  // Learns `scene` with `topology` into `model` and checks that it worked.
  void learn(const std::string& scene, const std::string& topology, const std::string& model) {
    expectSuccess(runIsm(dir_, learnArguments(demo_, scene, topology, model)));
  }
  ToolRun recognizeSet(const std::string& model, const std::string& scene, int set) {
    return runIsm(dir_, {"recognize", "--model", model, "--demo", demo_, "--scene", scene, "--set",
                         std::to_string(set), "--json"});
  }
  ToolRun recognizeObjects(const std::string& model, const std::string& scene,
                           const std::string& objects) {
    return runIsm(
        dir_, {"recognize", "--model", model, "--scene", scene, "--objects", objects, "--json"});
  }

  TempDir dir_;
  std::string demo_;
};

// ---- on the real recordings ----

class IsmToolOnRecordings : public IsmToolTest {
 protected:
  IsmToolOnRecordings() { demo_ = recording("story_1.sqlite"); }
  void SetUp() override { REQUIRE_RECORDINGS(); }
};

TEST_F(IsmToolOnRecordings, LearnStarAndCompleteThenInfo) {
  for (const char* topology : {"star", "complete"}) {
    SCOPED_TRACE(topology);
    const std::string model = dir_.file(std::string(topology) + ".sqlite");
    const ToolRun run = runIsm(dir_, learnArguments(demo_, "gedeck", topology, model));
    expectSuccess(run);
    EXPECT_EQ(run.out.rfind("learned scene 'gedeck' from " + demo_, 0), 0u) << run.out;
    expectInfoDescribes(dir_, model, "gedeck");
  }
  // The recording's table: 8 objects; a star relates the centre to 7, complete all 28 pairs.
  const IsmTree star = sqlite::loadIsmTree(dir_.file("star.sqlite"), "gedeck");
  const IsmTree complete = sqlite::loadIsmTree(dir_.file("complete.sqlite"), "gedeck");
  EXPECT_EQ(star.topology.relationCount(), 7u);
  EXPECT_EQ(star.isms.size(), 1u);
  EXPECT_EQ(complete.topology.relationCount(), 28u);
  EXPECT_GT(complete.height(), 1) << "a complete topology needs sub-ISMs";

  // Without --scene, info shows every model in the file.
  const ToolRun all = runIsm(dir_, {"info", "--model", dir_.file("complete.sqlite")});
  expectSuccess(all);
  EXPECT_NE(all.out.find("scene 'gedeck'"), std::string::npos) << all.out;
}

TEST_F(IsmToolOnRecordings, RecognizeARecordedSetAsJson) {
  for (const char* topology : {"star", "complete"}) {
    SCOPED_TRACE(topology);
    const std::string model = dir_.file(std::string(topology) + ".sqlite");
    learn("gedeck", topology, model);
    const ToolRun run = recognizeSet(model, "gedeck", 0);
    expectSuccess(run);
    const json output = parseRecognition(run, "gedeck");
    EXPECT_GE(bestConfidence(output), 0.99) << run.out;
    // All eight objects of the set are in the best instance, and none is missing.
    ASSERT_FALSE(output["instances"].empty());
    EXPECT_EQ(output["instances"][0]["objects"].size(), 8u);
    EXPECT_TRUE(output["instances"][0]["missing"].empty());
  }
}

TEST_F(IsmToolOnRecordings, RecognizeObjectsFilesInYamlAndJson) {
  const std::string model = dir_.file("complete.sqlite");
  learn("gedeck", "complete", model);
  const asr_common::Configuration set =
      asr_ism::sqlite::readDemonstration(demo_, "gedeck").configuration(5);
  const std::string yaml = dir_.file("set5.yaml");
  asr_ism::writeConfigurationFile(yaml, set);
  const std::string json_file = writeJsonObjects(dir_, "set5.json", set);

  const ToolRun from_demo = recognizeSet(model, "gedeck", 5);
  expectSuccess(from_demo);
  const json expected = parseRecognition(from_demo, "gedeck");
  EXPECT_GE(bestConfidence(expected), 0.99);
  for (const std::string& objects : {yaml, json_file}) {
    SCOPED_TRACE(objects);
    const ToolRun run = recognizeObjects(model, "gedeck", objects);
    expectSuccess(run);
    // The files hold the set's poses exactly, so the results are the recorded set's.
    EXPECT_EQ(parseRecognition(run, "gedeck")["instances"], expected["instances"]);
  }
  // The same without --json: a summary line and the best instance for a person to read.
  const ToolRun text =
      runIsm(dir_, {"recognize", "--model", model, "--scene", "gedeck", "--objects", yaml});
  expectSuccess(text);
  EXPECT_EQ(text.out.rfind("scene 'gedeck': ", 0), 0u) << text.out;
  EXPECT_NE(text.out.find("instance 1: confidence 1.000"), std::string::npos) << text.out;

  // Without ids (as most detectors report, and as the README's example allows) the objects match
  // by type: the same instance, and the output says the ids were ignored.
  asr_ism::Configuration types_only = set;
  for (auto& estimate : types_only)
    estimate.key.id.clear();
  const std::string types_file = dir_.file("set5_types.yaml");
  asr_ism::writeConfigurationFile(types_file, types_only);
  const json by_type = parseRecognition(recognizeObjects(model, "gedeck", types_file), "gedeck");
  ASSERT_FALSE(by_type["instances"].empty());
  EXPECT_EQ(by_type["instances"][0]["confidence"], expected["instances"][0]["confidence"]);
  EXPECT_EQ(by_type["instances"][0]["object_confidence"],
            expected["instances"][0]["object_confidence"]);
  EXPECT_EQ(by_type["instances"][0]["ids_ignored"], true);
  EXPECT_EQ(expected["instances"][0]["ids_ignored"], false);
  // The searches completed: the confidence is the exhaustive search's, not a lower bound.
  EXPECT_EQ(expected["instances"][0]["search_complete"], true);
  EXPECT_EQ(by_type["instances"][0]["search_complete"], true);
}

TEST_F(IsmToolOnRecordings, ErrorsNameTheInput) {
  const std::string model = dir_.file("star.sqlite");
  expectInputError(runIsm(dir_, learnArguments(demo_, "Kitchen_Sink", "star", model)),
                   {demo_, "Kitchen_Sink"});
  EXPECT_FALSE(std::filesystem::exists(model)) << "a failed learn creates no model file";
  learn("gedeck", "star", model);
  expectInputError(recognizeSet(model, "Kitchen_Sink", 0), {"Kitchen_Sink"});
  // gedeck has 112 sets: 0 to 111.
  expectInputError(recognizeSet(model, "gedeck", 112), {demo_, "gedeck", "112"});
  expectSuccess(recognizeSet(model, "gedeck", 111));
}

// ---- on small files written here (run without the recordings too) ----

class IsmToolOnSmallFiles : public IsmToolTest {
 protected:
  IsmToolOnSmallFiles() { demo_ = writeSmallDemonstration(dir_); }

  // An objects file with one object of "table" whose pose mapping is `pose`.
  std::string objectsFile(const std::string& name, const std::string& pose) {
    return dir_.write(name,
                      "objects:\n  - type: object_1\n    id: \"0\"\n    pose: " + pose + "\n");
  }
};

TEST_F(IsmToolOnSmallFiles, LearnInfoAndRecognize) {
  for (const char* topology : {"star", "complete"}) {
    SCOPED_TRACE(topology);
    const std::string model = dir_.file(std::string(topology) + ".sqlite");
    learn("table", topology, model);
    expectInfoDescribes(dir_, model, "table");
    const ToolRun run = recognizeSet(model, "table", 3);
    expectSuccess(run);
    const json from_set = parseRecognition(run, "table");
    EXPECT_GE(bestConfidence(from_set), 0.99) << run.out;

    const auto set = asr_ism::sqlite::readDemonstration(demo_, "table").configuration(3);
    const std::string yaml = dir_.file(std::string(topology) + "_set3.yaml");
    asr_ism::writeConfigurationFile(yaml, set);
    const std::string json_file = writeJsonObjects(dir_, std::string(topology) + "_set3.json", set);
    for (const std::string& objects : {yaml, json_file}) {
      const ToolRun from_file = recognizeObjects(model, "table", objects);
      expectSuccess(from_file);
      EXPECT_EQ(parseRecognition(from_file, "table")["instances"], from_set["instances"]);
    }
  }
}

TEST_F(IsmToolOnSmallFiles, MissingFilesAreNamed) {
  const std::string model = dir_.file("model.sqlite");
  const std::string absent_demo = dir_.file("absent_demo.sqlite");
  const std::string absent_model = dir_.file("absent_model.sqlite");
  expectInputError(runIsm(dir_, learnArguments(absent_demo, "table", "star", model)),
                   {absent_demo});
  learn("table", "star", model);
  expectInputError(recognizeSet(absent_model, "table", 0), {absent_model});
  expectInputError(runIsm(dir_, {"info", "--model", absent_model}), {absent_model});
  const std::string absent_objects = dir_.file("absent.yaml");
  expectInputError(recognizeObjects(model, "table", absent_objects), {absent_objects});
  const std::string absent_topology = dir_.file("absent_topology.txt");
  expectInputError(runIsm(dir_, learnArguments(demo_, "table", absent_topology, model)),
                   {absent_topology});
  EXPECT_FALSE(std::filesystem::exists(absent_demo));
  EXPECT_FALSE(std::filesystem::exists(absent_model));
}

TEST_F(IsmToolOnSmallFiles, UnknownScenesAreNamed) {
  const std::string model = dir_.file("model.sqlite");
  expectInputError(runIsm(dir_, learnArguments(demo_, "kitchen", "star", model)),
                   {demo_, "'kitchen'"});
  learn("table", "star", model);
  // The scene is in the demonstration but the model file has no model of it.
  const std::string objects = dir_.write("objects.yaml", "objects: []\n");
  expectInputError(recognizeObjects(model, "shelf", objects), {model, "'shelf'"});
  expectInputError(recognizeSet(model, "kitchen", 0), {demo_, "'kitchen'"});
  expectInputError(runIsm(dir_, {"info", "--model", model, "--scene", "kitchen"}),
                   {model, "'kitchen'"});
}

TEST_F(IsmToolOnSmallFiles, BadObjectsFilesAreNamed) {
  const std::string model = dir_.file("model.sqlite");
  learn("table", "complete", model);
  const std::string malformed =
      dir_.write("malformed.yaml", "objects:\n  - type: object_1\n    pose: {position: [\n");
  expectInputError(recognizeObjects(model, "table", malformed), {malformed, "malformed"});

  const std::string nan_pose = objectsFile(
      "nan.yaml", "{position: {x: .nan, y: 0, z: 0}, orientation: {x: 0, y: 0, z: 0, w: 1}}");
  expectInputError(recognizeObjects(model, "table", nan_pose),
                   {nan_pose, "object 0 (object_1:0)", "not finite"});

  const std::string zero_quaternion = objectsFile(
      "zero.yaml", "{position: {x: 1, y: 0, z: 0}, orientation: {x: 0, y: 0, z: 0, w: 0}}");
  expectInputError(recognizeObjects(model, "table", zero_quaternion),
                   {zero_quaternion, "object 0 (object_1:0)", "zero quaternion"});

  // A folder opens like a file but cannot be read.
  expectInputError(recognizeObjects(model, "table", dir_.path()), {dir_.path()});
}

TEST_F(IsmToolOnSmallFiles, EmptyDemonstrationIsNamed) {
  const std::string empty = writeEmptyDemonstration(dir_);
  const std::string model = dir_.file("model.sqlite");
  expectInputError(runIsm(dir_, learnArguments(empty, "nothing", "star", model)),
                   {empty, "'nothing'"});
  EXPECT_FALSE(std::filesystem::exists(model));
  learn("table", "star", model);
  expectInputError(runIsm(dir_, {"recognize", "--model", model, "--demo", empty, "--scene",
                                 "nothing", "--set", "0"}),
                   {empty, "'nothing'"});
}

TEST_F(IsmToolOnSmallFiles, SetOutOfRangeIsNamed) {
  const std::string model = dir_.file("model.sqlite");
  learn("table", "star", model);
  // "table" has 12 sets: 0 to 11.
  expectSuccess(recognizeSet(model, "table", 11));
  expectInputError(recognizeSet(model, "table", 12), {demo_, "'table'", "set 12"});
  // Beyond any integer: a usage error, not a wrapped-around number.
  expectUsageError(runIsm(dir_, {"recognize", "--model", model, "--demo", demo_, "--scene", "table",
                                 "--set", "99999999999999999999999"}),
                   "99999999999999999999999");
}

TEST_F(IsmToolOnSmallFiles, RequestLargerThanTheMaximumIsRefused) {
  const std::string model = dir_.file("model.sqlite");
  learn("table", "star", model);
  const auto recognizeWithMaximum = [&](const std::string& maximum) {
    return runIsm(dir_, {"recognize", "--model", model, "--demo", demo_, "--scene", "table",
                         "--set", "0", "--max-estimates", maximum});
  };
  // "table" has four objects per set.
  expectSuccess(recognizeWithMaximum("4"));
  expectInputError(recognizeWithMaximum("3"), {"4 object estimates", "maximum of 3"});
  expectUsageError(recognizeWithMaximum("0"), "--max-estimates");
}

TEST_F(IsmToolOnSmallFiles, DisconnectedTopologyIsNamed) {
  const std::string topology = dir_.write("topology.txt", "object_0 object_1\nobject_2 object_3\n");
  const std::string model = dir_.file("model.sqlite");
  expectInputError(runIsm(dir_, learnArguments(demo_, "table", topology, model)),
                   {topology, "not connected"});
  EXPECT_FALSE(std::filesystem::exists(model));
}

TEST_F(IsmToolOnSmallFiles, UsageErrors) {
  const std::string model = dir_.file("model.sqlite");
  expectUsageError(runIsm(dir_, {"learn", "--demo", demo_, "--scene", "table", "--topology", "star",
                                 "--model", model, "--bogus", "1"}),
                   "--bogus");
  expectUsageError(runIsm(dir_, {"info", "--model", model, "--verbose"}), "--verbose");
  expectUsageError(runIsm(dir_, {"learn", "--demo", demo_, "--scene", "table"}), "--topology");
  expectUsageError(runIsm(dir_, {"recognize", "--model", model, "--scene", "table"}), "--objects");
  expectUsageError(runIsm(dir_, {"frobnicate"}), "frobnicate");
  expectUsageError(runIsm(dir_, {}), "command");
  EXPECT_FALSE(std::filesystem::exists(model));

  const ToolRun help = runIsm(dir_, {"--help"});
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_EQ(help.out.rfind("usage: ism", 0), 0u) << help.out;
  EXPECT_TRUE(help.err.empty());
}

TEST_F(IsmToolOnSmallFiles, NumbersOutOfRangeAreRefusedNotTruncated) {
  // Before, --seed 4294967303 ran as --seed 7 and --max-height 4294967296 as unlimited.
  const std::vector<std::string> select = {"select-topology",
                                           "--demo",
                                           demo_,
                                           "--scene",
                                           "table",
                                           "--topology-out",
                                           dir_.file("topology.txt"),
                                           "--model",
                                           dir_.file("model.sqlite")};
  const std::pair<const char*, const char*> cases[] = {
      {"--seed", "4294967303"},  {"--seed", "-1"},        {"--max-height", "4294967296"},
      {"--tests", "1000000000"}, {"--threads", "100000"}, {"--max-evaluations", "1"},
      {"--bin-size", "1e300"},   {"--bin-size", "0"},     {"--tests", "60x"}};
  for (const auto& [option, value] : cases) {
    std::vector<std::string> arguments = select;
    arguments.insert(arguments.end(), {option, value});
    expectUsageError(runIsm(dir_, arguments), option);
  }
  EXPECT_FALSE(std::filesystem::exists(dir_.file("model.sqlite")));
  EXPECT_FALSE(std::filesystem::exists(dir_.file("topology.txt")));
}

TEST_F(IsmToolOnSmallFiles, ObjectsFilesWithTrailingTextOrARepeatedKeyAreRefused) {
  const std::string model = dir_.file("model.sqlite");
  learn("table", "star", model);
  const std::string pose =
      "{position: {x: 0, y: 0, z: 0.75}, orientation: {x: 0, y: 0, z: 0, w: 1}}";
  const std::string trailing = dir_.write(
      "trailing.json",
      "{\"objects\": [{\"type\": \"object_1\", \"id\": \"0\", \"pose\": " + pose + "}]} garbage\n");
  expectInputError(recognizeObjects(model, "table", trailing), {trailing, "after the objects"});
  const std::string twice = objectsFile("twice.yaml", pose + "\n    id: \"1\"");
  expectInputError(recognizeObjects(model, "table", twice), {twice, "'id' is given twice"});
}

TEST_F(IsmToolOnSmallFiles, InfoSaysWhichModelIsInvalid) {
  const std::string model = dir_.file("model.sqlite");
  learn("table", "star", model);
  learn("shelf", "star", model);
  asr_ism::sqlite::Database(model, asr_ism::sqlite::Database::Mode::kReadWriteCreate)
      .execute("UPDATE asr_ism_trees SET bin_size = 1e300 WHERE scene = 'shelf'");
  const ToolRun info = runIsm(dir_, {"info", "--model", model});
  EXPECT_EQ(info.exit_code, 1) << describe(info);
  EXPECT_NE(info.out.find("scene 'table': 4 objects"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("scene 'shelf': INVALID model"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("bin_size 1e+300 m"), std::string::npos) << info.out;
  ASSERT_EQ(info.err.size(), 1u) << describe(info);
  EXPECT_NE(info.err[0].find("1 of 2 scene models are invalid"), std::string::npos) << info.err[0];
  expectInputError(recognizeSet(model, "shelf", 0), {model, "bin_size"});
}

TEST_F(IsmToolOnSmallFiles, ErrorsStayOnOneLine) {
  // Names with line breaks (from the command line or a file) must not split the error line.
  const std::string model = dir_.file("model.sqlite");
  expectInputError(runIsm(dir_, learnArguments(demo_, "two\nlines", "star", model)),
                   {"two\\nlines"});
  learn("table", "star", model);
  const std::string objects = dir_.write(
      "objects.yaml", "objects:\n  - {type: \"a\\nb\", pose: {position: {x: 1, y: 0, z: 0}}}\n");
  expectInputError(recognizeObjects(model, "table", objects), {objects, "a\\nb", "orientation"});
}

// ---- the model file is never half-written ----

TEST_F(IsmToolOnSmallFiles, FailedLearnLeavesTheModelFileByteIdentical) {
  const std::string model = dir_.file("model.sqlite");
  learn("table", "complete", model);
  const std::string before = fileBytes(model);
  ASSERT_FALSE(before.empty());
  const auto entries = dir_.entries();

  const std::string disconnected = dir_.write("topology.txt", "object_0 object_1\n");
  expectInputError(runIsm(dir_, learnArguments(demo_, "table", disconnected, model)),
                   {disconnected});
  expectInputError(runIsm(dir_, learnArguments(demo_, "kitchen", "star", model)), {"'kitchen'"});
  expectInputError(
      runIsm(dir_, learnArguments(writeEmptyDemonstration(dir_), "nothing", "star", model)),
      {"'nothing'"});
  EXPECT_EQ(fileBytes(model), before);
  // Nothing but the inputs written above is left beside it (no journal, no temporary file).
  for (const std::string& entry : dir_.entries()) {
    const bool known = std::find(entries.begin(), entries.end(), entry) != entries.end() ||
                       entry == "topology.txt" || entry == "empty_demo.sqlite";
    EXPECT_TRUE(known) << entry;
  }
  expectInfoDescribes(dir_, model, "table");
}

TEST_F(IsmToolOnSmallFiles, SecondSceneKeepsTheFirstLoadable) {
  const std::string model = dir_.file("model.sqlite");
  learn("table", "complete", model);
  const ToolRun table_before = recognizeSet(model, "table", 4);
  expectSuccess(table_before);

  learn("shelf", "star", model);
  const ToolRun info = runIsm(dir_, {"info", "--model", model});
  expectSuccess(info);
  EXPECT_NE(info.out.find("scene 'table'"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("scene 'shelf'"), std::string::npos) << info.out;
  EXPECT_EQ(sqlite::listModelScenes(model), (std::vector<std::string>{"table", "shelf"}));

  const ToolRun table_after = recognizeSet(model, "table", 4);
  expectSuccess(table_after);
  EXPECT_EQ(parseRecognition(table_after, "table")["instances"],
            parseRecognition(table_before, "table")["instances"]);
  const ToolRun shelf = recognizeSet(model, "shelf", 2);
  expectSuccess(shelf);
  EXPECT_GE(bestConfidence(parseRecognition(shelf, "shelf")), 0.99) << shelf.out;
}

}  // namespace
}  // namespace asr_ism_tree

namespace asr_ism_tree {
namespace {

// ---- select-topology ----

std::vector<std::string> selectArguments(const std::string& demo, const std::string& scene,
                                         const TempDir& dir) {
  return {"select-topology",
          "--demo",
          demo,
          "--scene",
          scene,
          "--topology-out",
          dir.file("topology.txt"),
          "--model",
          dir.file("model.sqlite"),
          "--tests",
          "60",
          "--max-evaluations",
          "12",
          "--seed",
          "3"};
}

TEST_F(IsmToolOnRecordings, SelectTopologyWritesATopologyThatLearnReadsBack) {
  const std::string demo = recording("story_2.sqlite");
  std::vector<std::string> arguments = selectArguments(demo, "Getraenke_Regal", dir_);
  arguments.insert(arguments.end(), {"--tests-out", dir_.file("tests.sqlite")});
  const ToolRun run = runIsm(dir_, arguments);
  EXPECT_EQ(run.exit_code, 0) << describe(run);
  EXPECT_NE(run.out.find("optimised"), std::string::npos) << run.out;
  // Progress goes to stderr while it runs.
  ASSERT_FALSE(run.err.empty());
  EXPECT_NE(run.err[0].find("topologies"), std::string::npos) << run.err[0];
  const IsmTree selected = sqlite::loadIsmTree(dir_.file("model.sqlite"), "Getraenke_Regal");
  EXPECT_TRUE(selected.topology.isConnected());

  // The topology file is what `learn --topology FILE` reads; the stored tests repeat the run.
  const std::string relearned = dir_.file("relearned.sqlite");
  expectSuccess(
      runIsm(dir_, learnArguments(demo, "Getraenke_Regal", dir_.file("topology.txt"), relearned)));
  EXPECT_EQ(sqlite::loadIsmTree(relearned, "Getraenke_Regal").topology, selected.topology);
  std::vector<std::string> repeat = selectArguments(demo, "Getraenke_Regal", dir_);
  repeat[6] = dir_.file("topology2.txt");
  repeat[8] = dir_.file("model2.sqlite");
  repeat.insert(repeat.end(), {"--tests-in", dir_.file("tests.sqlite")});
  const ToolRun again = runIsm(dir_, repeat);
  EXPECT_EQ(again.exit_code, 0) << describe(again);
  EXPECT_EQ(fileBytes(dir_.file("topology2.txt")), fileBytes(dir_.file("topology.txt")));
}

TEST_F(IsmToolOnRecordings, SelectTopologyBadInputIsNamed) {
  const std::string demo = recording("story_2.sqlite");
  std::vector<std::string> zero = selectArguments(demo, "Getraenke_Regal", dir_);
  zero[10] = "0";  // --tests 0
  const ToolRun no_tests = runIsm(dir_, zero);
  EXPECT_EQ(no_tests.exit_code, 2) << describe(no_tests);
  ASSERT_FALSE(no_tests.err.empty());
  EXPECT_NE(no_tests.err[0].find("--tests"), std::string::npos) << no_tests.err[0];

  const std::string disconnected =
      dir_.write("start.txt",
                 "Cup:011021054100 marker_10:052052051100\nMultivitaminJuice:0 Sprudelflasche:0\n");
  std::vector<std::string> with_start = selectArguments(demo, "Getraenke_Regal", dir_);
  with_start.insert(with_start.end(), {"--start", disconnected});
  expectInputError(runIsm(dir_, with_start), {disconnected, "not connected"});

  const std::string unknown = dir_.write("unknown.txt", "Teapot:0 Cup:011021054100\n");
  with_start.back() = unknown;
  expectInputError(runIsm(dir_, with_start), {unknown, "Teapot"});
  EXPECT_FALSE(std::filesystem::exists(dir_.file("model.sqlite")));
}

}  // namespace
}  // namespace asr_ism_tree
