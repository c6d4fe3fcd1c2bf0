// `asr search` and learn_kitchen_models run as a user runs them.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "asr_common/testing/recordings_skip.hpp"
#include "asr_common/testing/tool_run.hpp"

namespace {

using asr_common::testing::describe;
using asr_common::testing::runTool;
using asr_common::testing::TempDir;

const std::string kKitchen =
    std::string(ASR_STATE_MACHINE_SOURCE_DIR) + "/config/worlds/kitchen.yaml";

// Exit code 1, nothing on stdout, one line on stderr naming `name`.
void expectRefused(const asr_common::testing::ToolRun& run, const std::string& name) {
  EXPECT_EQ(run.exit_code, 1) << describe(run);
  EXPECT_TRUE(run.out.empty()) << describe(run);
  ASSERT_EQ(run.err.size(), 1u) << describe(run);
  EXPECT_EQ(run.err[0].rfind("asr search", 0), 0u) << run.err[0];
  EXPECT_NE(run.err[0].find(name), std::string::npos) << run.err[0];
}

TEST(SearchTool, LearnsTheKitchenAndSearchesItToTheEnd) {
  REQUIRE_RECORDINGS();
  TempDir dir("search_tool");
  const std::string models = dir.file("kitchen.sqlite");
  const auto learned =
      runTool(LEARN_TOOL, dir,
              {"--model", models, "--recordings", asr_common::testing::recordings(), "--world-out",
               dir.file("kitchen.yaml")});
  ASSERT_EQ(learned.exit_code, 0) << describe(learned);
  EXPECT_EQ(asr_common::testing::fileBytes(dir.file("kitchen.yaml")),
            asr_common::testing::fileBytes(kKitchen));

  const std::string png = dir.file("search.png");
  const auto run = runTool(SEARCH_TOOL, dir,
                           {"--world", kKitchen, "--models", models, "--mode", "asr", "--seed", "3",
                            "--json", "--png", png});
  ASSERT_EQ(run.exit_code, 0) << describe(run);
  // The picture is a PNG; a saved result gives the same JSON and picture again.
  const std::string picture = asr_common::testing::fileBytes(png);
  ASSERT_GT(picture.size(), 1000u);
  EXPECT_EQ(picture.substr(1, 3), "PNG");
  const std::string saved = dir.write("result.json", run.out);
  const auto again =
      runTool(SEARCH_TOOL, dir,
              {"--world", kKitchen, "--result", saved, "--json", "--png", dir.file("again.png")});
  ASSERT_EQ(again.exit_code, 0) << describe(again);
  // (A saved result keeps the total compute, not the time of every decision.)
  nlohmann::json first = nlohmann::json::parse(run.out), second = nlohmann::json::parse(again.out);
  first.erase("decision_compute_ms_median");
  second.erase("decision_compute_ms_median");
  EXPECT_EQ(second, first);
  EXPECT_EQ(asr_common::testing::fileBytes(dir.file("again.png")), picture);
  const nlohmann::json result = nlohmann::json::parse(run.out);
  EXPECT_EQ(result["outcome"], "found_all_objects");
  EXPECT_EQ(result["reason"], "");
  EXPECT_GT(result["sim_seconds"].get<double>(), 0.0);
  EXPECT_GE(result["compute_seconds"].get<double>(), 0.0);
  EXPECT_EQ(result["found"].size(), 14u);
  for (const auto& found : result["found"]) {
    EXPECT_TRUE(found.contains("type") && found.contains("id") && found.contains("pose"));
    EXPECT_LE(found["found_at_s"].get<double>(), result["sim_seconds"].get<double>());
    EXPECT_LT(found["view"].get<int>(), result["views"].get<int>());
  }
  EXPECT_EQ(result["scenes"].size(), 3u);
  EXPECT_EQ(result["log"].back()["event"], "found_all_objects");
}

TEST(SearchTool, BadInputEndsWithOneLineNamingIt) {
  REQUIRE_RECORDINGS();
  TempDir dir("search_tool_bad");
  const std::string models = dir.file("kitchen.sqlite");
  ASSERT_EQ(runTool(LEARN_TOOL, dir, {"--model", models}).exit_code, 0);
  expectRefused(runTool(SEARCH_TOOL, dir,
                        {"--world", dir.file("nowhere.yaml"), "--models", models, "--json"}),
                "nowhere.yaml");
  expectRefused(runTool(SEARCH_TOOL, dir,
                        {"--world", kKitchen, "--models", dir.file("none.sqlite"), "--json"}),
                "none.sqlite");
  expectRefused(runTool(SEARCH_TOOL, dir,
                        {"--world", kKitchen, "--models", models, "--scenes", "lunch", "--json"}),
                "lunch");
  expectRefused(
      runTool(SEARCH_TOOL, dir,
              {"--world", kKitchen, "--models", models, "--required", "lunch:0.85", "--json"}),
      "lunch");
  expectRefused(runTool(SEARCH_TOOL, dir,
                        {"--world", kKitchen, "--models", models, "--mode", "random", "--json"}),
                "random");
  // A picture that cannot be written is refused before the search.
  expectRefused(
      runTool(SEARCH_TOOL, dir,
              {"--world", kKitchen, "--models", models, "--png", dir.file("no_folder/search.png")}),
      "no_folder/search.png");
  expectRefused(runTool(SEARCH_TOOL, dir, {"--world", kKitchen, "--result", dir.file("none.json")}),
                "none.json");
  // A malformed command line is a usage error (exit code 2).
  EXPECT_EQ(runTool(SEARCH_TOOL, dir,
                    {"--world", kKitchen, "--models", models, "--required", "gedeck", "--json"})
                .exit_code,
            2);
}

}  // namespace
