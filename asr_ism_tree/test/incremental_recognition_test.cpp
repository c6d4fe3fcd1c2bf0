// Continuous recognition of changing estimates (IncrementalRecognition) and the parallel
// recognition of several scenes (SceneModels), on three kitchen scenes of the recordings.

#include "asr_ism_tree/incremental_recognition.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <set>
#include <string>

#include "asr_common/input_error.hpp"
#include "asr_common/testing/input_error_of.hpp"
#include "asr_common/testing/recordings_skip.hpp"
#include "asr_common/testing/temp_dir.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"
#include "asr_ism_tree/scene_models.hpp"
#include "asr_ism_tree/sqlite/model_store.hpp"
#include "asr_ism_tree/tree_generation.hpp"

namespace asr_ism_tree {
namespace {

using asr_common::Configuration;
using asr_common::ObjectEstimate;
using asr_common::testing::inputErrorOf;
using asr_common::testing::recording;
using asr_common::testing::TempDir;

struct KitchenScene {
  const char* file;
  const char* scene;
};

// Scenes that share some types (PlateDeep in all three, marker_1 and marker_5 in two) and not
// others.
const KitchenScene kScenes[] = {{"story_1.sqlite", "gedeck"},
                                {"story_2.sqlite", "Brot_Regal"},
                                {"story_2.sqlite", "Muesli_Gedeck"}};

// Lower work limits than the defaults: the estimates below see most scenes badly, and the
// searches' limits are not under test here, only that reused answers equal fresh ones.
TreeRecognitionParameters quickParameters() {
  TreeRecognitionParameters parameters;
  parameters.exact_search_max_comparisons = 200000;
  parameters.diverse_max_comparisons = 200000;
  parameters.object_subsets_max_work = 1000000;
  return parameters;
}

// The complete trees of kScenes saved in `dir`, loaded; the first set of every scene, one estimate
// per object (the first scene's where scenes share one), as the world the walk below starts from.
struct Kitchen {
  std::vector<std::string> model_files;
  Configuration world;
};

Kitchen learnKitchen(const TempDir& dir) {
  Kitchen kitchen;
  for (const KitchenScene& scene : kScenes) {
    const asr_ism::Demonstration demonstration =
        asr_ism::sqlite::readDemonstration(recording(scene.file), scene.scene);
    const std::string model = dir.file(std::string(scene.scene) + ".sqlite");
    sqlite::saveIsmTree(
        model,
        generateIsmTree(demonstration, RelationTopology::complete(demonstration.objects()), {}),
        "test");
    kitchen.model_files.push_back(model);
    for (const ObjectEstimate& estimate : demonstration.configuration(0)) {
      if (std::none_of(kitchen.world.begin(), kitchen.world.end(),
                       [&](const auto& kept) { return kept.key == estimate.key; }))
        kitchen.world.push_back(estimate);
    }
  }
  return kitchen;
}

void expectSameInstances(const std::vector<SceneInstance>& got,
                         const std::vector<SceneInstance>& expected, const std::string& what) {
  ASSERT_EQ(got.size(), expected.size()) << what;
  for (std::size_t i = 0; i < got.size(); ++i) {
    const SceneInstance& a = got[i];
    const SceneInstance& b = expected[i];
    EXPECT_EQ(a.scene, b.scene) << what;
    EXPECT_EQ(a.confidence, b.confidence) << what << " " << a.scene;
    EXPECT_EQ(a.object_confidence, b.object_confidence) << what << " " << a.scene;
    EXPECT_EQ(a.search_complete, b.search_complete) << what << " " << a.scene;
    EXPECT_EQ(a.ids_ignored, b.ids_ignored) << what << " " << a.scene;
    EXPECT_EQ(a.pose.position, b.pose.position) << what << " " << a.scene;
    EXPECT_EQ(a.missing, b.missing) << what << " " << a.scene;
    ASSERT_EQ(a.objects.size(), b.objects.size()) << what << " " << a.scene;
    for (std::size_t o = 0; o < a.objects.size(); ++o) {
      EXPECT_EQ(a.objects[o].key, b.objects[o].key) << what << " " << a.scene;
      EXPECT_EQ(a.objects[o].estimate, b.objects[o].estimate) << what << " " << a.scene;
      EXPECT_EQ(a.objects[o].similarity, b.objects[o].similarity) << what << " " << a.scene;
      EXPECT_EQ(a.objects[o].pose.position, b.objects[o].pose.position) << what << " " << a.scene;
    }
  }
}

// One random change to the estimates a robot keeps; returns the type it touched ("" for none or
// clutter: no scene has it).
std::string changeRandomly(Configuration& estimates, Configuration& removed, std::mt19937& random) {
  std::uniform_int_distribution<std::size_t> action(0, 6);
  std::normal_distribution<double> jitter(0.0, 0.02);
  const auto pick = [&](const Configuration& from) {
    return std::uniform_int_distribution<std::size_t>(0, from.size() - 1)(random);
  };
  switch (action(random)) {
    case 0: {  // seen again, a little elsewhere
      ObjectEstimate& moved = estimates[pick(estimates)];
      moved.pose.position += Eigen::Vector3d(jitter(random), jitter(random), jitter(random));
      return moved.key.type;
    }
    case 1: {  // lost (estimate_timeout)
      if (estimates.size() < 4)
        return "";
      const std::size_t i = pick(estimates);
      removed.push_back(estimates[i]);
      estimates.erase(estimates.begin() + static_cast<long>(i));
      return removed.back().key.type;
    }
    case 2: {  // found again
      if (removed.empty())
        return "";
      estimates.push_back(removed.back());
      removed.pop_back();
      return estimates.back().key.type;
    }
    case 3: {  // an object no scene knows
      ObjectEstimate clutter;
      clutter.key = {"Vase", std::to_string(random() % 3)};
      clutter.pose.position = Eigen::Vector3d(jitter(random), jitter(random), 0.0) * 50.0;
      clutter.pose.orientation = Eigen::Quaterniond::Identity();
      estimates.insert(estimates.begin() + static_cast<long>(pick(estimates)), clutter);
      return "";
    }
    case 4: {  // a repeated detection of an object
      ObjectEstimate repeat = estimates[pick(estimates)];
      repeat.pose.position += Eigen::Vector3d(jitter(random), 0.0, 0.0) * 0.1;
      estimates.push_back(repeat);
      return repeat.key.type;
    }
    case 5: {  // a detector that reports the type only
      ObjectEstimate typed = estimates[pick(estimates)];
      typed.key.id.clear();
      typed.pose.position += Eigen::Vector3d(0.0, 0.3, 0.0);
      estimates.push_back(typed);
      return typed.key.type;
    }
    default:  // nothing new
      return "";
  }
}

TEST(IncrementalRecognition, EqualsRecognisingEverySceneAnewOverARandomWalk) {
  REQUIRE_RECORDINGS();
  TempDir dir("asr_incremental");
  const Kitchen kitchen = learnKitchen(dir);
  const auto models = std::make_shared<const SceneModels>(
      SceneModels::load(kitchen.model_files, {}, quickParameters()));
  IncrementalRecognition incremental;
  Configuration estimates = kitchen.world;
  Configuration removed;
  std::mt19937 random(12);
  expectSameInstances(incremental.recognize(models, estimates), models->recognize(estimates),
                      "first");
  EXPECT_EQ(incremental.scenesRecognizedAnew(), 3u);
  std::size_t reused = 0;
  for (int step = 0; step < 100; ++step) {
    const std::string type = changeRandomly(estimates, removed, random);
    const std::string what = "step " + std::to_string(step) + " (" + type + ")";
    expectSameInstances(incremental.recognize(models, estimates), models->recognize(estimates),
                        what);
    // Only the scenes that have the changed type are recognised anew (a clutter change,
    // or no change, costs none).
    EXPECT_EQ(incremental.scenesRecognizedAnew(), type.empty() ? 0 : models->scenesWithType(type))
        << what;
    reused += 3 - incremental.scenesRecognizedAnew();
  }
  EXPECT_GT(reused, 100u);  // the walk exercised the reuse, not only fresh recognitions
}

TEST(IncrementalRecognition, NewModelsOrARefusalLeaveNothingToReuse) {
  REQUIRE_RECORDINGS();
  TempDir dir("asr_incremental");
  const Kitchen kitchen = learnKitchen(dir);
  TreeRecognitionParameters parameters = quickParameters();
  parameters.max_estimates = kitchen.world.size();
  const auto models =
      std::make_shared<const SceneModels>(SceneModels::load(kitchen.model_files, {}, parameters));
  IncrementalRecognition incremental;
  incremental.recognize(models, kitchen.world);
  incremental.recognize(models, kitchen.world);
  EXPECT_EQ(incremental.scenesRecognizedAnew(), 0u);

  // One estimate too many, of a type no scene has: refused as every scene refuses it.
  Configuration too_many = kitchen.world;
  too_many.push_back({{"Vase", "1"}, kitchen.world.front().pose});
  EXPECT_THROW(models->recognize(too_many), asr_common::InputError);
  EXPECT_THROW(incremental.recognize(models, too_many), asr_common::InputError);
  expectSameInstances(incremental.recognize(models, kitchen.world),
                      models->recognize(kitchen.world), "after the refusal");
  EXPECT_EQ(incremental.scenesRecognizedAnew(), 3u);

  // An invalid pose, even of an object no scene has, is refused as recognising anew refuses it.
  Configuration invalid(kitchen.world.begin(), kitchen.world.end() - 1);
  incremental.recognize(models, invalid);
  invalid.push_back({{"Vase", "1"}, kitchen.world.front().pose});
  invalid.back().pose.position.x() = std::nan("");
  const std::string expected = inputErrorOf([&] { models->recognize(invalid); });
  EXPECT_NE(expected.find("(Vase:1)"), std::string::npos) << expected;
  EXPECT_EQ(inputErrorOf([&] { incremental.recognize(models, invalid); }), expected);

  const auto reloaded =
      std::make_shared<const SceneModels>(SceneModels::load(kitchen.model_files, {}, parameters));
  incremental.recognize(reloaded, kitchen.world);
  EXPECT_EQ(incremental.scenesRecognizedAnew(), 3u);
}

TEST(SceneModels, ParallelRecognitionEqualsSerial) {
  REQUIRE_RECORDINGS();
  TempDir dir("asr_incremental");
  const Kitchen kitchen = learnKitchen(dir);
  const SceneModels serial = SceneModels::load(kitchen.model_files, {}, quickParameters(), 1);
  const SceneModels parallel = SceneModels::load(kitchen.model_files, {}, quickParameters(), 3);
  for (const KitchenScene& scene : kScenes) {
    const asr_ism::Demonstration demonstration =
        asr_ism::sqlite::readDemonstration(recording(scene.file), scene.scene);
    for (std::size_t set = 0; set < demonstration.stepCount(); set += 3) {
      const Configuration configuration = demonstration.configuration(set);
      const std::string what = std::string(scene.scene) + " set " + std::to_string(set);
      expectSameInstances(parallel.recognize(configuration), serial.recognize(configuration), what);
      expectSameInstances(parallel.recognize(configuration, {scene.scene}),
                          serial.recognize(configuration, {scene.scene}), what);
    }
  }
}

TEST(SceneModels, TheErrorOfTheFirstSceneIsReportedWhateverTheThreadsTiming) {
  REQUIRE_RECORDINGS();
  TempDir dir("asr_incremental");
  const Kitchen kitchen = learnKitchen(dir);
  TreeRecognitionParameters parameters = quickParameters();
  parameters.max_estimates = 1;
  const SceneModels models = SceneModels::load(kitchen.model_files, {}, parameters, 3);
  for (int attempt = 0; attempt < 20; ++attempt) {
    try {
      models.recognize(kitchen.world);
      ADD_FAILURE() << "too many estimates were not refused";
    } catch (const asr_common::InputError& error) {
      EXPECT_NE(std::string(error.what()).find("scene 'gedeck'"), std::string::npos)
          << error.what();
    }
  }
}

}  // namespace
}  // namespace asr_ism_tree
