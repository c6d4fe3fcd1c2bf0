// System test: search.launch on a kitchen whose breakfast cup is missing. Searching for every
// object ends `nowhere_left_to_search` within its simulated budget, with every object that is
// there found and the cup not; requiring only the crispbread shelf (Brot_Regal at 0.5) ends
// `found_all_required_scenes`. Wall-clock waits are hang guards only.
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>

#include "asr_common/testing/rostest_support.hpp"
#include "asr_common/testing/temp_dir.hpp"
#include "search_launch.hpp"

namespace asr_integration_tests {
namespace {

constexpr double kBudgetMinutes = 120.0;
const char* const kWorld = "kitchen_without_cup.yaml";

std::set<std::string> foundKeys(const nlohmann::json& result) {
  std::set<std::string> keys;
  for (const auto& found : result["found"])
    keys.insert(found["type"].get<std::string>() + ":" + found["id"].get<std::string>());
  return keys;
}

TEST(AbsentObject, TheVariantWorldIsTheKitchenWithoutItsCup) {
  // Lines of the kitchen without the header comments and the cup's three lines.
  const auto body = [](const std::string& path, bool drop_cup) {
    std::ifstream file(path);
    std::vector<std::string> lines;
    for (std::string line; std::getline(file, line);) {
      if (line.rfind("#", 0) == 0)
        continue;
      lines.push_back(line);
    }
    for (std::size_t i = 0; drop_cup && i < lines.size(); ++i) {
      if (lines[i] == "  - type: Cup") {
        lines.erase(lines.begin() + i, lines.begin() + i + 3);
        break;
      }
    }
    return lines;
  };
  const auto kitchen = body(kitchenWorld(), true);
  ASSERT_GT(kitchen.size(), 20u);
  EXPECT_EQ(body(testFile(kWorld), false), kitchen);
}

TEST(AbsentObject, SearchingForEveryObjectEndsNowhereLeftToSearch) {
  SearchLaunch launch("absent_all",
                      {"world:=" + testFile(kWorld), "model_files:=[" + kitchenModels() + "]",
                       "seed:=2", "max_sim_minutes:=" + std::to_string(kBudgetMinutes)});
  const auto result = launch.waitForResult();
  ASSERT_TRUE(result) << "no result; last state " << launch.lastState() << "\n" << launch.logTail();
  EXPECT_EQ((*result)["outcome"], "nowhere_left_to_search") << result->dump(1);
  EXPECT_LE((*result)["sim_seconds"].get<double>(), 60.0 * kBudgetMinutes);
  const std::set<std::string> found = foundKeys(*result);
  EXPECT_EQ(found.count("Cup:011021054100"), 0u);
  // Every other object of the three scenes is there and found (13 of the kitchen's 14).
  EXPECT_EQ(found.size(), 13u) << result->dump(1);
  EXPECT_TRUE(launch.waitForState("nowhere_left_to_search", 30.0)) << launch.lastState();
}

TEST(AbsentObject, RequiringOneSceneEndsFoundAllRequiredScenes) {
  SearchLaunch launch("absent_required",
                      {"world:=" + testFile(kWorld), "model_files:=[" + kitchenModels() + "]",
                       "seed:=3", "required:={Brot_Regal: 0.5}",
                       "max_sim_minutes:=" + std::to_string(kBudgetMinutes)});
  const auto result = launch.waitForResult();
  ASSERT_TRUE(result) << "no result; last state " << launch.lastState() << "\n" << launch.logTail();
  EXPECT_EQ((*result)["outcome"], "found_all_required_scenes") << result->dump(1);
  EXPECT_LE((*result)["sim_seconds"].get<double>(), 60.0 * kBudgetMinutes);
  for (const auto& scene : (*result)["scenes"]) {
    if (scene["scene"] == "Brot_Regal") {
      EXPECT_GE(scene["confidence"].get<double>(), 0.5) << scene.dump();
    }
  }
  EXPECT_EQ(foundKeys(*result).count("Cup:011021054100"), 0u);
}

}  // namespace
}  // namespace asr_integration_tests

int main(int argc, char** argv) {
  return asr_common::testing::runRostests(argc, argv, "absent_object_rostest");
}
