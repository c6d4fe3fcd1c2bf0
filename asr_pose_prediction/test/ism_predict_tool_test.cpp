// End-to-end tests of the built `asr ism predict` tool (ISM_PREDICT_TOOL) as a user runs it: a
// recorded set of the real recordings with objects left out, JSON and text output, and the
// errors for a scene without a tree and for objects in which no instance is found.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "asr_common/testing/recordings_skip.hpp"
#include "asr_common/testing/temp_dir.hpp"
#include "asr_common/testing/tool_run.hpp"
#include "asr_ism/configuration_file.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"
#include "asr_ism_tree/sqlite/model_store.hpp"
#include "asr_ism_tree/tree_generation.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"
#include "asr_pose_prediction/pose_cloud_summary.hpp"
#include "asr_pose_prediction/pose_predictor.hpp"

#ifndef ISM_PREDICT_TOOL
#error "ISM_PREDICT_TOOL must be the path of the built ism_predict executable"
#endif

namespace asr_pose_prediction {
namespace {

using asr_common::testing::expectInputError;
using asr_common::testing::expectSuccess;
using asr_common::testing::TempDir;
using asr_common::testing::ToolRun;
using nlohmann::json;

class IsmPredictTool : public ::testing::Test {
 protected:
  void SetUp() override {
    REQUIRE_RECORDINGS();
    demonstration_ = asr_ism::sqlite::readDemonstration(
        asr_common::testing::recording("story_2.sqlite"), "Brot_Regal");
    tree_ = asr_ism_tree::generateIsmTree(
        demonstration_, asr_ism_tree::RelationTopology::complete(demonstration_.objects()), {});
    model_ = dir_.file("model.sqlite");
    asr_ism_tree::sqlite::saveIsmTree(model_, tree_, "story_2.sqlite");
  }

  // What the library predicts for recorded set `step` without the types in `left_out`: the
  // values the tool must print.
  std::vector<ObjectPrediction> libraryPrediction(std::size_t step,
                                                  const std::set<std::string>& left_out,
                                                  std::size_t samples, std::uint32_t seed) const {
    asr_common::Configuration kept;
    for (const asr_common::ObjectEstimate& estimate : demonstration_.configuration(step)) {
      if (!left_out.count(estimate.key.type))
        kept.push_back(estimate);
    }
    PredictionOptions options;
    options.samples = samples;
    options.seed = seed;
    return PosePredictor(tree_).predict(asr_ism_tree::TreeRecognizer(tree_).recognize(kept),
                                        options);
  }

  // Recorded set `step` without the objects of the types in `left_out`, as a YAML objects file.
  std::string objectsFile(std::size_t step, const std::set<std::string>& left_out) {
    asr_common::Configuration kept;
    for (const asr_common::ObjectEstimate& estimate : demonstration_.configuration(step)) {
      if (!left_out.count(estimate.key.type))
        kept.push_back(estimate);
    }
    const std::string path = dir_.file("objects_" + std::to_string(step) + ".yaml");
    asr_ism::writeConfigurationFile(path, kept);
    return path;
  }

  ToolRun predict(const std::vector<std::string>& arguments) {
    return asr_common::testing::runTool(ISM_PREDICT_TOOL, dir_, arguments);
  }

  TempDir dir_{"asr_ism_predict_tool"};
  asr_ism::Demonstration demonstration_;
  asr_ism_tree::IsmTree tree_;
  std::string model_;
};

TEST_F(IsmPredictTool, PredictsTheLeftOutObjectsAsJson) {
  const asr_common::Configuration full = demonstration_.configuration(10);
  // Not the root ISM's reference: its pose follows from the instance's exactly, whatever the
  // seed, so it would not show whether the tool draws what the library draws.
  const asr_common::ObjectEstimate left_out =
      full.front().key == tree_.isms[0].reference ? full[1] : full.front();
  const std::string objects = objectsFile(10, {left_out.key.type});

  const ToolRun run = predict({"--model", model_, "--scene", "Brot_Regal", "--objects", objects,
                               "--samples", "200", "--seed", "3", "--json"});
  expectSuccess(run);
  const json output = json::parse(run.out);
  EXPECT_EQ(output["scene"], "Brot_Regal");
  EXPECT_GE(output["instance_confidence"].get<double>(), (full.size() - 1.0) / full.size() - 0.02);
  ASSERT_EQ(output["predictions"].size(), 1u) << run.out;
  const json& prediction = output["predictions"][0];
  EXPECT_EQ(prediction["type"], left_out.key.type);
  EXPECT_EQ(prediction["id"], left_out.key.id);
  ASSERT_FALSE(prediction["path"].empty());
  EXPECT_EQ(prediction["path"][0], "Brot_Regal");
  ASSERT_EQ(prediction["poses"].size(), 200u);

  // The left-out object's recorded pose is among the predictions, to a few centimetres.
  double nearest = INFINITY;
  for (const json& pose : prediction["poses"]) {
    const Eigen::Vector3d position(pose["position"]["x"].get<double>(),
                                   pose["position"]["y"].get<double>(),
                                   pose["position"]["z"].get<double>());
    nearest = std::min(nearest, (position - left_out.pose.position).norm());
  }
  EXPECT_LT(nearest, 0.05);

  // Every printed pose is the library's, to the last digit (JSON keeps doubles exact).
  const std::vector<ObjectPrediction> expected = libraryPrediction(10, {left_out.key.type}, 200, 3);
  ASSERT_EQ(expected.size(), 1u);
  ASSERT_EQ(expected[0].poses.size(), prediction["poses"].size());
  for (std::size_t i = 0; i < expected[0].poses.size(); ++i) {
    const asr_common::Pose& pose = expected[0].poses[i];
    const json& printed = prediction["poses"][i];
    EXPECT_EQ(printed["position"]["x"].get<double>(), pose.position.x()) << i;
    EXPECT_EQ(printed["position"]["y"].get<double>(), pose.position.y()) << i;
    EXPECT_EQ(printed["position"]["z"].get<double>(), pose.position.z()) << i;
    EXPECT_EQ(printed["orientation"]["w"].get<double>(), pose.orientation.w()) << i;
    EXPECT_EQ(printed["orientation"]["z"].get<double>(), pose.orientation.z()) << i;
  }
  const double runtime_ms = output["runtime_ms"].get<double>();
  EXPECT_TRUE(std::isfinite(runtime_ms) && runtime_ms >= 0.0) << runtime_ms;

  // Same seed, same output (but for the runtime).
  const ToolRun again = predict({"--model", model_, "--scene", "Brot_Regal", "--objects", objects,
                                 "--samples", "200", "--seed", "3", "--json"});
  json first = output;
  json second = json::parse(again.out);
  first.erase("runtime_ms");
  second.erase("runtime_ms");
  EXPECT_EQ(first, second);
}

TEST_F(IsmPredictTool, SummaryGivesMeanAndSpreadPerObject) {
  const asr_common::Configuration full = demonstration_.configuration(20);
  const std::string objects = objectsFile(20, {full[0].key.type, full[1].key.type});
  const ToolRun run =
      predict({"--model", model_, "--scene", "Brot_Regal", "--objects", objects, "--summary"});
  expectSuccess(run);
  for (const std::string& type : {full[0].key.type, full[1].key.type})
    EXPECT_NE(run.out.find(type), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("mean"), std::string::npos) << run.out;

  const ToolRun as_json = predict(
      {"--model", model_, "--scene", "Brot_Regal", "--objects", objects, "--summary", "--json"});
  expectSuccess(as_json);
  const json output = json::parse(as_json.out);
  const std::vector<ObjectPrediction> expected =
      libraryPrediction(20, {full[0].key.type, full[1].key.type}, 100, 0);
  ASSERT_EQ(output["predictions"].size(), expected.size());
  ASSERT_EQ(expected.size(), 2u);
  for (std::size_t k = 0; k < expected.size(); ++k) {
    const json& printed = output["predictions"][k];
    ASSERT_TRUE(printed.contains("summary")) << printed.dump();
    EXPECT_EQ(printed["type"], expected[k].object.type);
    const PoseCloudSummary summary = summarizePoseCloud(expected[k].poses);
    const json& mean = printed["summary"]["mean_position"];
    EXPECT_EQ(mean["x"].get<double>(), summary.mean_position.x());
    EXPECT_EQ(mean["y"].get<double>(), summary.mean_position.y());
    EXPECT_EQ(mean["z"].get<double>(), summary.mean_position.z());
    EXPECT_EQ(printed["summary"]["position_rms_m"].get<double>(), summary.position_rms);
    EXPECT_EQ(printed["summary"]["position_max_m"].get<double>(), summary.position_max);
    // The text names each object with its mean position as the library computes it.
    char text_mean[64];
    std::snprintf(text_mean, sizeof text_mean, "(%.4f, %.4f, %.4f)", summary.mean_position.x(),
                  summary.mean_position.y(), summary.mean_position.z());
    EXPECT_NE(run.out.find(text_mean), std::string::npos) << text_mean << "\n" << run.out;
  }
}

TEST_F(IsmPredictTool, HideLeavesTypesOutOfARecordedSet) {
  const asr_common::Configuration full = demonstration_.configuration(10);
  const std::string hidden = full[0].key.type + "," + full[1].key.type;
  const ToolRun run = predict({"--model", model_, "--scene", "Brot_Regal", "--demo",
                               asr_common::testing::recording("story_2.sqlite"), "--set", "10",
                               "--hide", hidden, "--samples", "20", "--json"});
  expectSuccess(run);
  const json output = json::parse(run.out);
  const std::vector<ObjectPrediction> expected =
      libraryPrediction(10, {full[0].key.type, full[1].key.type}, 20, 0);
  ASSERT_EQ(output["predictions"].size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) {
    EXPECT_EQ(output["predictions"][k]["type"], expected[k].object.type);
    EXPECT_EQ(output["predictions"][k]["poses"][0]["position"]["x"].get<double>(),
              expected[k].poses[0].position.x());
  }
  expectInputError(predict({"--model", model_, "--scene", "Brot_Regal", "--demo",
                            asr_common::testing::recording("story_2.sqlite"), "--set", "10",
                            "--hide", "Teapot"}),
                   {"--hide", "Teapot", "Brot_Regal"});
}

TEST_F(IsmPredictTool, ASceneWithoutATreeIsNamed) {
  const std::string objects = objectsFile(0, {});
  expectInputError(predict({"--model", model_, "--scene", "Muesli_Regal", "--objects", objects}),
                   {"Muesli_Regal", model_});
}

TEST_F(IsmPredictTool, NoInstanceIsAnErrorNotAnEmptySuccess) {
  // Clutter only: objects of types the scene does not have.
  asr_common::Configuration clutter;
  for (asr_common::ObjectEstimate estimate : demonstration_.configuration(0)) {
    estimate.key.type = "Clutter_" + estimate.key.type;
    clutter.push_back(estimate);
  }
  const std::string objects = dir_.file("clutter.yaml");
  asr_ism::writeConfigurationFile(objects, clutter);
  expectInputError(predict({"--model", model_, "--scene", "Brot_Regal", "--objects", objects}),
                   {"no instance", "Brot_Regal", objects});
}

}  // namespace
}  // namespace asr_pose_prediction
