// End-to-end tests of the built `asr ism predict` tool (ISM_PREDICT_TOOL) as a user runs it: a
// recorded set of the real recordings with objects left out, JSON and text output, and the
// errors for a scene without a tree and for objects in which no instance is found.

#include <gtest/gtest.h>

#include <cmath>
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
    const asr_ism_tree::IsmTree tree = asr_ism_tree::generateIsmTree(
        demonstration_, asr_ism_tree::RelationTopology::complete(demonstration_.objects()), {});
    model_ = dir_.file("model.sqlite");
    asr_ism_tree::sqlite::saveIsmTree(model_, tree, "story_2.sqlite");
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
  std::string model_;
};

TEST_F(IsmPredictTool, PredictsTheLeftOutObjectsAsJson) {
  const asr_common::Configuration full = demonstration_.configuration(10);
  const asr_common::ObjectEstimate left_out = full.front();
  const std::string objects = objectsFile(10, {left_out.key.type});

  const ToolRun run = predict({"--model", model_, "--scene", "Brot_Regal", "--objects", objects,
                               "--samples", "200", "--seed", "3", "--json"});
  expectSuccess(run);
  const json output = json::parse(run.out);
  EXPECT_EQ(output["scene"], "Brot_Regal");
  EXPECT_GE(output["instance_confidence"].get<double>(), (full.size() - 1.0) / full.size() - 0.02);
  EXPECT_GE(output["runtime_ms"].get<double>(), 0.0);
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
  ASSERT_EQ(output["predictions"].size(), 2u);
  for (const json& prediction : output["predictions"])
    EXPECT_TRUE(prediction.contains("summary")) << prediction.dump();
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
