// No single input brings recognition down: what is accepted (estimates, demonstrations, models
// within input_limits.hpp) recognises without failing, and what is not is refused where it
// enters, naming the file and the field.

#include <gtest/gtest.h>

#include <random>

#include "asr_common/testing/input_error_of.hpp"
#include "asr_common/testing/temp_dir.hpp"
#include "asr_ism/input_limits.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"
#include "asr_ism/sqlite/demonstration_writer.hpp"
#include "asr_ism/sqlite/sqlite_database.hpp"
#include "asr_ism/synthetic_demonstration.hpp"
#include "asr_ism_tree/scene_models.hpp"
#include "asr_ism_tree/sqlite/model_store.hpp"
#include "asr_ism_tree/tree_generation.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"

namespace asr_ism_tree {
namespace {

using asr_common::testing::inputErrorOf;
using asr_common::testing::TempDir;
using asr_ism::Demonstration;
using asr_ism::Pose;
using asr_ism::sqlite::Database;

// A demonstration of `objects` objects spread over up to `extent` metres, placed at `centre`.
Demonstration spreadDemonstration(std::size_t objects, double extent, const Eigen::Vector3d& centre,
                                  std::mt19937& random) {
  std::uniform_real_distribution<double> unit(-0.5, 0.5);
  std::vector<asr_ism::ObjectKey> keys;
  for (std::size_t i = 0; i < objects; ++i)
    keys.push_back({"object_" + std::to_string(i), ""});
  Demonstration demonstration("spread", keys);
  std::vector<Eigen::Vector3d> places;
  for (std::size_t i = 0; i < objects; ++i)
    places.push_back(centre + extent * Eigen::Vector3d(unit(random), unit(random), unit(random)));
  for (std::size_t step = 0; step < 4; ++step) {
    demonstration.addStep();
    for (std::size_t i = 0; i < objects; ++i) {
      const Eigen::Quaterniond turn(Eigen::AngleAxisd(unit(random), Eigen::Vector3d::UnitZ()));
      demonstration.setPose(step, i, Pose(places[i] + 0.01 * Eigen::Vector3d::Random(), turn));
    }
  }
  return demonstration;
}

TEST(InputValidation, AcceptedModelsRecogniseAcceptedEstimatesWithoutFailing) {
  // Property: scenes spanning up to the relation limit, anywhere up to the coordinate limit,
  // learned with any accepted bin size as star or complete trees, recognise any accepted
  // estimates (their own, and ones anywhere in the accepted cube) without an exception.
  std::mt19937 random(12);
  std::uniform_real_distribution<double> coordinate(-asr_ism::kMaxCoordinate,
                                                    asr_ism::kMaxCoordinate);
  std::uniform_real_distribution<double> log_bin(std::log(asr_ism::kMinBinSize),
                                                 std::log(asr_ism::kMaxBinSize));
  const double extent = asr_ism::kMaxRelationLength / std::sqrt(3.0) * 0.999;
  for (int trial = 0; trial < 40; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const double edge = asr_ism::kMaxCoordinate - extent / 2;
    const Eigen::Vector3d centre(trial % 2 ? edge : -edge, coordinate(random) * 0.9, -edge);
    const Demonstration demonstration = spreadDemonstration(2 + trial % 5, extent, centre, random);
    asr_ism::IsmRecognitionParameters parameters;
    parameters.bin_size = std::exp(log_bin(random));
    const RelationTopology topology = trial % 3 == 0
                                          ? RelationTopology::star(demonstration.objects(), 0)
                                          : RelationTopology::complete(demonstration.objects());
    const IsmTree tree = generateIsmTree(demonstration, topology, parameters);
    const TreeRecognizer recognizer(tree);
    asr_ism::Configuration anywhere = demonstration.configuration(1);
    for (auto& estimate : anywhere)
      estimate.pose.position =
          Eigen::Vector3d(coordinate(random), coordinate(random), coordinate(random));
    EXPECT_FALSE(recognizer.recognize(demonstration.configuration(2)).empty());
    EXPECT_NO_THROW(recognizer.recognize(anywhere));
  }
}

// A demonstration file of the suite's breakfast scene, with one SQL change applied.
std::string breakfastFile(const TempDir& dir, const std::string& change) {
  const std::string path = dir.file("breakfast.sqlite");
  asr_ism::sqlite::appendDemonstration(path, asr_ism::makeBreakfastDemonstration(3));
  Database(path, Database::Mode::kReadWriteCreate).execute(change);
  return path;
}

TEST(InputValidation, DemonstrationsRefuseFarPosesNullTypesAndTwoPosesPerSet) {
  TempDir dir("asr_input_validation");
  const struct {
    std::string change;
    std::vector<std::string> named;
  } cases[] = {
      {"UPDATE recorded_poses SET px = 1e7 WHERE id = 5", {"recorded_poses id 5", "1000 m"}},
      {"UPDATE recorded_poses SET qx = 'abc' WHERE id = 7", {"recorded_poses id 7", "qx", "abc"}},
      {"UPDATE recorded_objects SET type = NULL WHERE id = 2", {"recorded_objects id 2", "NULL"}},
      {"INSERT INTO recorded_poses (objectId, setId, px, py, pz, qw, qx, qy, qz) "
       "SELECT objectId, setId, px + 0.5, py, pz, qw, qx, qy, qz FROM recorded_poses WHERE id = 9",
       {"second pose", "recorded_poses id 9"}},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.change);
    std::filesystem::remove(dir.file("breakfast.sqlite"));
    const std::string path = breakfastFile(dir, c.change);
    const std::string message =
        inputErrorOf([&] { asr_ism::sqlite::readDemonstration(path, "breakfast"); });
    EXPECT_NE(message.find(path), std::string::npos) << message;
    for (const std::string& part : c.named)
      EXPECT_NE(message.find(part), std::string::npos) << message;
  }
}

TEST(InputValidation, TheModelLoaderRefusesWhatTheDemonstrationReaderRefuses) {
  TempDir dir("asr_input_validation");
  const Demonstration demonstration = asr_ism::makeBreakfastDemonstration(3);
  const std::string good = dir.file("good.sqlite");
  sqlite::saveIsmTree(
      good, generateIsmTree(demonstration, RelationTopology::complete(demonstration.objects()), {}),
      "test");
  const struct {
    std::string change;
    std::vector<std::string> named;
  } cases[] = {
      {"UPDATE asr_ism_trees SET bin_size = 0", {"bin_size 0 m"}},
      {"UPDATE asr_ism_trees SET bin_size = -0.1", {"bin_size -0.1 m"}},
      {"UPDATE asr_ism_trees SET bin_size = 1e999", {"bin_size inf m"}},
      // With such a bin, a cup 50 cm from its place scored 1.000.
      {"UPDATE asr_ism_trees SET bin_size = 1e300", {"bin_size 1e+300 m"}},
      {"UPDATE asr_ism_trees SET bin_size = 'wide'", {"bin_size", "wide"}},
      {"UPDATE asr_ism_trees SET max_angle_deviation = '30 deg'",
       {"max_angle_deviation", "30 deg"}},
      {"UPDATE asr_ism_relative_poses SET px = 'x' WHERE ism = 0 AND member = 1 AND position = 0",
       {"asr_ism_relative_poses (ism 0, member 1, position 0)", "px", "'x'"}},
      {"UPDATE asr_ism_relative_poses SET py = 500 WHERE position = 0 AND member = 1",
       {"more than the 100 m"}},
      {"UPDATE asr_ism_relative_poses SET pz = 1e7 WHERE position = 0 AND member = 1", {"1000 m"}},
      {"UPDATE asr_ism_relative_poses SET step_count = 0", {"step_count"}},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.change);
    const std::string path = dir.file("edited.sqlite");
    std::filesystem::copy_file(good, path, std::filesystem::copy_options::overwrite_existing);
    Database(path, Database::Mode::kReadWriteCreate).execute(c.change);
    const std::string message = inputErrorOf([&] { sqlite::loadIsmTree(path, "breakfast"); });
    EXPECT_NE(message.find(path + ", scene 'breakfast'"), std::string::npos) << message;
    for (const std::string& part : c.named)
      EXPECT_NE(message.find(part), std::string::npos) << message;
    // A recogniser never starts with it.
    EXPECT_THROW(SceneModels::load({path}), asr_ism::InputError);
  }
}

TEST(InputValidation, ASceneAskedForTwiceIsAnsweredOnce) {
  TempDir dir("asr_input_validation");
  const Demonstration demonstration = asr_ism::makeBreakfastDemonstration(3);
  const std::string path = dir.file("model.sqlite");
  sqlite::saveIsmTree(
      path, generateIsmTree(demonstration, RelationTopology::complete(demonstration.objects()), {}),
      "test");
  const SceneModels models = SceneModels::load({path}, {"breakfast", "breakfast"});
  const auto once = models.recognize(demonstration.configuration(4), {"breakfast"});
  const auto twice = models.recognize(demonstration.configuration(4), {"breakfast", "breakfast"});
  ASSERT_FALSE(once.empty());
  EXPECT_EQ(twice.size(), once.size());
}

}  // namespace
}  // namespace asr_ism_tree
