// Continuous recognition of changing estimates (ContinuousRecognition) and the parallel
// recognition of several scenes (SceneModels), on three kitchen scenes of the recordings.

#include "asr_ism_tree/continuous_recognition.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
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

// What the scenes' threads threw, for the test to check.
class Errors {
 public:
  std::function<void(std::exception_ptr)> handler() {
    return [this](std::exception_ptr error) {
      std::lock_guard<std::mutex> lock(mutex_);
      try {
        std::rethrow_exception(error);
      } catch (const std::exception& e) {
        messages_.push_back(e.what());
      }
    };
  }
  std::vector<std::string> messages() {
    std::lock_guard<std::mutex> lock(mutex_);
    return messages_;
  }

 private:
  std::mutex mutex_;
  std::vector<std::string> messages_;
};

// Each scene's latest result equals recognising that scene anew in `estimates`, bit for bit,
// each object naming the same estimate (its `estimate` indexes the result's own configuration,
// which may be an earlier one with the same estimates of the scene's types).
void expectEachSceneAsRecognisedAnew(const ContinuousRecognition::Latest& latest,
                                     const SceneModels& models, const Configuration& estimates,
                                     const std::string& what) {
  ASSERT_EQ(latest.scenes.size(), models.scenes().size()) << what;
  for (std::size_t scene = 0; scene < latest.scenes.size(); ++scene) {
    ASSERT_TRUE(latest.scenes[scene].has_value()) << what << " scene " << scene;
    const ContinuousRecognition::SceneResult& result = *latest.scenes[scene];
    std::vector<SceneInstance> got = result.instances;
    for (SceneInstance& instance : got) {
      for (InstanceObject& object : instance.objects) {
        const ObjectEstimate& named = result.configuration->at(object.estimate);
        const auto same = std::find_if(estimates.begin(), estimates.end(), [&](const auto& e) {
          return e.key == named.key && e.pose.position == named.pose.position &&
                 e.pose.orientation.coeffs() == named.pose.orientation.coeffs();
        });
        ASSERT_NE(same, estimates.end()) << what << ": an estimate no longer seen";
        object.estimate = static_cast<int>(same - estimates.begin());
      }
    }
    expectSameInstances(got, models.recognizeEach({scene}, estimates).front(),
                        what + " scene " + models.scenes()[scene]);
  }
}

std::shared_ptr<const Configuration> shared(const Configuration& estimates) {
  return std::make_shared<const Configuration>(estimates);
}

// Offers `estimates` until every scene's result is of them: the slots leave slow scenes behind
// for later offers, as a node's next ticks would offer them.
void settle(ContinuousRecognition& continuous, const std::shared_ptr<const SceneModels>& models,
            const Configuration& estimates, std::uint64_t stamp) {
  const auto offered = shared(estimates);
  for (std::size_t round = 0; round <= models->scenes().size(); ++round) {
    continuous.offer(models, offered, stamp);
    continuous.waitUntilIdle();
    if (continuous.settled())
      return;
  }
  ADD_FAILURE() << "not settled after one offer per scene";
}

// The three kitchen scenes learned and loaded with the lower limits; what the scenes' threads
// throw fails the test.
class ContinuousRecognitionTest : public ::testing::Test {
 protected:
  void SetUp() override {
    REQUIRE_RECORDINGS();
    kitchen = learnKitchen(dir);
    models = std::make_shared<const SceneModels>(
        SceneModels::load(kitchen.model_files, {}, quickParameters()));
  }
  void TearDown() override { EXPECT_TRUE(errors.messages().empty()); }

  TempDir dir{"asr_continuous"};
  Kitchen kitchen;
  std::shared_ptr<const SceneModels> models;
  Errors errors;
};

TEST_F(ContinuousRecognitionTest, EachSceneEqualsRecognisingItAnewOverARandomWalk) {
  // One slow recognition at a time, none quick: the slots decide what starts when.
  ContinuousRecognition continuous(errors.handler(), {1, 0.0});
  Configuration estimates = kitchen.world;
  Configuration removed;
  std::mt19937 random(12);
  settle(continuous, models, estimates, 0);
  ContinuousRecognition::Latest latest = continuous.latest();
  EXPECT_EQ(latest.fresh, 3u);
  expectEachSceneAsRecognisedAnew(latest, *models, estimates, "first");
  std::size_t reused = 0;
  for (std::uint64_t step = 1; step <= 100; ++step) {
    const std::string type = changeRandomly(estimates, removed, random);
    const std::string what = "step " + std::to_string(step) + " (" + type + ")";
    settle(continuous, models, estimates, step);
    latest = continuous.latest();
    expectEachSceneAsRecognisedAnew(latest, *models, estimates, what);
    // Only the scenes that have the changed type are recognised anew (a clutter change, or no
    // change, costs none), and every result is that of this offer's estimates, so it carries
    // its stamp.
    EXPECT_EQ(latest.fresh, type.empty() ? 0 : models->scenesWithType(type)) << what;
    for (const auto& result : latest.scenes)
      EXPECT_EQ(result->stamp, step) << what;
    reused += 3 - latest.fresh;
  }
  EXPECT_GT(reused, 100u);  // the walk exercised the reuse, not only fresh recognitions
}

TEST_F(ContinuousRecognitionTest, ScenesLeftBehindByABusyThreadCatchUpAtALaterOffer) {
  // Every scene quick once recognised (each on its thread whenever free), and one slot.
  ContinuousRecognition continuous(errors.handler(), {1, 1e9});
  Configuration estimates = kitchen.world;
  Configuration removed;
  std::mt19937 random(5);
  // Offered faster than recognised: whichever scenes' threads or the slot are busy fall behind
  // (which ones depends on the machine; the answer after catching up must not).
  for (std::uint64_t step = 0; step < 30; ++step) {
    changeRandomly(estimates, removed, random);
    continuous.offer(models, shared(estimates), step);
  }
  settle(continuous, models, estimates, 30);
  expectEachSceneAsRecognisedAnew(continuous.latest(), *models, estimates, "caught up");
  continuous.offer(models, shared(estimates), 31);
  continuous.waitUntilIdle();
  EXPECT_EQ(continuous.latest().fresh, 0u);  // nothing left to recognise
}

// Which scenes have a result, and its stamp (-1: none).
std::vector<long long> stampsOf(const ContinuousRecognition::Latest& latest) {
  std::vector<long long> stamps;
  for (const auto& result : latest.scenes)
    stamps.push_back(result ? static_cast<long long>(result->stamp) : -1);
  return stamps;
}

TEST_F(ContinuousRecognitionTest, SlowScenesTakeTurnsOldestResultFirst) {
  ContinuousRecognition continuous(errors.handler(), {1, 0.0});  // one at a time, none quick
  const auto offerAndWait = [&](const Configuration& estimates, std::uint64_t stamp) {
    continuous.offer(models, shared(estimates), stamp);
    continuous.waitUntilIdle();
    return stampsOf(continuous.latest());
  };
  // No results yet: in scene order, one per offer; a scene whose estimates are unchanged stands
  // for the estimates of each later offer.
  EXPECT_EQ(offerAndWait(kitchen.world, 1), (std::vector<long long>{1, -1, -1}));
  EXPECT_EQ(offerAndWait(kitchen.world, 2), (std::vector<long long>{2, 2, -1}));
  EXPECT_EQ(offerAndWait(kitchen.world, 3), (std::vector<long long>{3, 3, 3}));
  EXPECT_TRUE(continuous.settled());
  // A plate (all three scenes have the type) seen anew, twice: each offer starts the scene
  // whose result is oldest, so none waits for more than a round.
  Configuration moved = kitchen.world;
  const auto plate = std::find_if(moved.begin(), moved.end(),
                                  [](const auto& e) { return e.key.type == "PlateDeep"; });
  ASSERT_NE(plate, moved.end());
  plate->pose.position.x() += 0.01;
  EXPECT_EQ(offerAndWait(moved, 4), (std::vector<long long>{4, 3, 3}));
  plate->pose.position.x() += 0.01;
  EXPECT_EQ(offerAndWait(moved, 5), (std::vector<long long>{4, 5, 3}));
  EXPECT_EQ(offerAndWait(moved, 6), (std::vector<long long>{4, 6, 6}));  // 1 is current
  EXPECT_EQ(offerAndWait(moved, 7), (std::vector<long long>{7, 7, 7}));
  EXPECT_TRUE(continuous.settled());
  expectEachSceneAsRecognisedAnew(continuous.latest(), *models, moved, "after the turns");
}

TEST_F(ContinuousRecognitionTest, QuickScenesStartWithoutASlot) {
  // One slot, and a period of 1e9 s: once known, every scene is quick.
  ContinuousRecognition continuous(errors.handler(), {1, 1e9});
  settle(continuous, models, kitchen.world, 1);  // unknown until recognised: one at a time
  Configuration moved = kitchen.world;
  const auto plate = std::find_if(moved.begin(), moved.end(),
                                  [](const auto& e) { return e.key.type == "PlateDeep"; });
  ASSERT_NE(plate, moved.end());
  plate->pose.position.x() += 0.01;
  continuous.offer(models, shared(moved), 2);
  continuous.waitUntilIdle();
  EXPECT_TRUE(continuous.settled());  // all three started at once
  EXPECT_EQ(stampsOf(continuous.latest()), (std::vector<long long>{2, 2, 2}));
}

TEST_F(ContinuousRecognitionTest, NewModelsOrARefusalDropEveryResult) {
  TreeRecognitionParameters parameters = quickParameters();
  parameters.max_estimates = kitchen.world.size();
  models =
      std::make_shared<const SceneModels>(SceneModels::load(kitchen.model_files, {}, parameters));
  ContinuousRecognition continuous(errors.handler());
  const auto recognize = [&](const std::shared_ptr<const SceneModels>& with,
                             const Configuration& estimates) {
    settle(continuous, with, estimates, 0);
    return continuous.latest();
  };
  EXPECT_EQ(recognize(models, kitchen.world).fresh, 3u);
  EXPECT_EQ(recognize(models, kitchen.world).fresh, 0u);

  // One estimate too many, of a type no scene has: refused as every scene refuses it.
  Configuration too_many = kitchen.world;
  too_many.push_back({{"Vase", "1"}, kitchen.world.front().pose});
  EXPECT_THROW(models->recognize(too_many), asr_common::InputError);
  EXPECT_THROW(continuous.offer(models, shared(too_many), 1), asr_common::InputError);
  for (const auto& result : continuous.latest().scenes)
    EXPECT_FALSE(result.has_value());
  const ContinuousRecognition::Latest after_refusal = recognize(models, kitchen.world);
  EXPECT_EQ(after_refusal.fresh, 3u);
  expectEachSceneAsRecognisedAnew(after_refusal, *models, kitchen.world, "after the refusal");

  // An invalid pose, even of an object no scene has, is refused as recognising anew refuses it.
  Configuration invalid(kitchen.world.begin(), kitchen.world.end() - 1);
  recognize(models, invalid);
  invalid.push_back({{"Vase", "1"}, kitchen.world.front().pose});
  invalid.back().pose.position.x() = std::nan("");
  const std::string expected = inputErrorOf([&] { models->recognize(invalid); });
  EXPECT_NE(expected.find("(Vase:1)"), std::string::npos) << expected;
  EXPECT_EQ(inputErrorOf([&] { continuous.offer(models, shared(invalid), 2); }), expected);
  for (const auto& result : continuous.latest().scenes)
    EXPECT_FALSE(result.has_value());

  const auto reloaded =
      std::make_shared<const SceneModels>(SceneModels::load(kitchen.model_files, {}, parameters));
  recognize(models, kitchen.world);
  EXPECT_EQ(recognize(reloaded, kitchen.world).fresh, 3u);
}

TEST(SceneModels, ParallelRecognitionEqualsSerial) {
  REQUIRE_RECORDINGS();
  TempDir dir("asr_continuous");
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
  TempDir dir("asr_continuous");
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
