// The in-process search of the shipped kitchen with models learned from the real recordings.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>

#include "asr_common/input_error.hpp"
#include "asr_common/testing/recordings_skip.hpp"
#include "asr_common/testing/temp_dir.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"
#include "asr_robot_model/world.hpp"
#include "asr_state_machine/in_process_search.hpp"
#include "asr_state_machine/kitchen.hpp"
#include "asr_state_machine/search_json.hpp"

namespace asr_state_machine {
namespace {

using asr_common::testing::TempDir;

const std::string kKitchen =
    std::string(ASR_STATE_MACHINE_SOURCE_DIR) + "/config/worlds/kitchen.yaml";

// The kitchen's models, learned once for all tests of this file.
class KitchenSearch : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (asr_common::testing::recordings().empty())
      return;
    models_ = new TempDir("kitchen_models");
    kitchen::learnKitchenModels(asr_common::testing::recordings(), modelFile());
  }
  static void TearDownTestSuite() {
    delete models_;
    models_ = nullptr;
  }
  static std::string modelFile() { return models_->file("kitchen.sqlite"); }

  static SearchRequest request(SearchMode mode, std::uint32_t seed) {
    SearchRequest request;
    request.world = kKitchen;
    request.model_files = {modelFile()};
    request.config.mode = mode;
    request.config.seed = seed;
    return request;
  }

  static TempDir* models_;
};
TempDir* KitchenSearch::models_ = nullptr;

TEST_F(KitchenSearch, TheShippedWorldIsWhatTheKitchenToolWrites) {
  REQUIRE_RECORDINGS();
  EXPECT_EQ(asr_common::testing::fileBytes(kKitchen),
            kitchen::kitchenWorldYaml(asr_common::testing::recordings()))
      << "regenerate it: learn_kitchen_models --model M --world-out " << kKitchen;
}

TEST_F(KitchenSearch, TheHeldOutSetIsNotLearnedFrom) {
  REQUIRE_RECORDINGS();
  const asr_ism::Demonstration all = asr_ism::sqlite::readDemonstration(
      asr_common::testing::recording("story_1.sqlite"), "gedeck");
  const std::size_t held_out = kitchen::heldOutStep(all);
  const asr_ism::Demonstration training = kitchen::withoutStep(all, held_out);
  EXPECT_EQ(training.stepCount(), all.stepCount() - 1);
  EXPECT_EQ(all.configuration(held_out).size(), all.objectCount());
}

TEST_F(KitchenSearch, ActiveSceneRecognitionFindsEveryObjectOfTheKitchen) {
  REQUIRE_RECORDINGS();
  const asr_robot_model::World world = asr_robot_model::loadWorld(
      kKitchen, asr_robot_model::loadObjectCatalogue(asr_robot_model::defaultObjectCatalogue()));
  InProcessSearch search(request(SearchMode::kAsr, 1));
  const SearchResult result = search.run();
  EXPECT_EQ(result.outcome, Outcome::kFoundAllObjects) << result.reason;
  EXPECT_TRUE(result.world.missingObjects().empty());
  // Every found object of a scene is where the world has it (clutter is never searched).
  for (const FoundObject& found : result.world.foundObjects()) {
    const auto truth = std::find_if(world.objects.begin(), world.objects.end(),
                                    [&](const auto& object) { return object.key == found.key; });
    ASSERT_NE(truth, world.objects.end()) << found.key.toString();
    EXPECT_LT((truth->box.pose.position - found.pose.position).norm(), 0.05);
  }
  for (const auto& [scene, confidence] : result.world.sceneConfidences()) {
    EXPECT_GT(confidence, 0.5) << scene;
  }
}

// Without scene knowledge, next-best-views over the furniture and then the sweep find everything
// too, only later (seed 1 missed the plate while the sweep skipped views near ones that had
// searched other types only).
TEST_F(KitchenSearch, BoundingBoxSearchFindsEveryObjectOfTheKitchen) {
  REQUIRE_RECORDINGS();
  const SearchResult result = InProcessSearch(request(SearchMode::kBoundingBox, 1)).run();
  EXPECT_EQ(result.outcome, Outcome::kFoundAllObjects) << result.reason;
  EXPECT_TRUE(result.world.missingObjects().empty());
}

TEST_F(KitchenSearch, ASearchIsTheSameForTheSameSeed) {
  REQUIRE_RECORDINGS();
  const auto withoutCompute = [](const SearchResult& result) {
    nlohmann::ordered_json json = searchResultJson(result);
    json.erase("compute_seconds");
    json.erase("decision_compute_ms_median");
    for (auto& entry : json["log"])
      entry.erase("compute_ms");
    return json.dump();
  };
  const std::string first = withoutCompute(InProcessSearch(request(SearchMode::kAsr, 4)).run());
  const std::string second = withoutCompute(InProcessSearch(request(SearchMode::kAsr, 4)).run());
  EXPECT_EQ(first, second);
}

TEST_F(KitchenSearch, AnAbsentObjectEndsTheSearchWithoutFindingIt) {
  REQUIRE_RECORDINGS();
  TempDir folder("kitchen_absent");
  // The milk is taken off the shelf.
  const std::string text = asr_common::testing::fileBytes(kKitchen);
  const std::regex milk("  - type: HMilkBio\n    id: \"0\"\n    pose: [^\n]*\n");
  const std::string without = std::regex_replace(text, milk, "");
  ASSERT_NE(without, text);
  SearchRequest absent = request(SearchMode::kAsr, 2);
  absent.world = folder.write("kitchen_without_milk.yaml", without);
  const SearchResult result = InProcessSearch(absent).run();
  EXPECT_EQ(result.outcome, Outcome::kNowhereLeftToSearch) << result.reason;
  EXPECT_EQ(result.world.missingObjects(), (std::vector<ObjectKey>{{"HMilkBio", "0"}}));

  // With the breakfast setting required, the search ends as soon as it is recognised.
  absent.config.required_scenes = {{"gedeck", 0.85}};
  const SearchResult required = InProcessSearch(absent).run();
  EXPECT_EQ(required.outcome, Outcome::kFoundAllRequiredScenes) << required.reason;
  EXPECT_GE(required.world.sceneConfidence("gedeck"), 0.85);
  EXPECT_LT(required.sim_seconds, result.sim_seconds);
}

TEST_F(KitchenSearch, BadInputIsRefusedBeforeAnythingMoves) {
  REQUIRE_RECORDINGS();
  SearchRequest bad = request(SearchMode::kAsr, 0);
  bad.world = "/nonexistent/kitchen.yaml";
  EXPECT_THROW(InProcessSearch{bad}, asr_common::InputError);
  bad = request(SearchMode::kAsr, 0);
  bad.model_files = {"/nonexistent/models.sqlite"};
  EXPECT_THROW(InProcessSearch{bad}, asr_common::InputError);
  bad = request(SearchMode::kAsr, 0);
  bad.scenes = {"lunch"};
  EXPECT_THROW(InProcessSearch{bad}, asr_common::InputError);
  bad = request(SearchMode::kAsr, 0);
  bad.config.required_scenes = {{"lunch", 0.85}};
  try {
    InProcessSearch search(bad);
    FAIL() << "a required scene no model holds was accepted";
  } catch (const asr_common::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("lunch"), std::string::npos);
  }
}

}  // namespace
}  // namespace asr_state_machine
