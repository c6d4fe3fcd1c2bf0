// Reading predicted clouds (the output of `asr ism predict --json`) and visited views.
#include <gtest/gtest.h>

#include <fstream>

#include "asr_common/input_error.hpp"
#include "asr_common/testing/temp_dir.hpp"
#include "asr_nbv/nbv_documents.hpp"

namespace asr_nbv {
namespace {

using asr_common::testing::TempDir;

std::string write(const TempDir& dir, const std::string& name, const std::string& text) {
  const std::string path = dir.file(name);
  std::ofstream(path) << text;
  return path;
}

const char* const kPrediction = R"({"scene": "breakfast", "instance_confidence": 0.8,
  "runtime_ms": 1.0, "predictions": [
  {"type": "Cup", "id": "0", "path": ["Plate", "Cup"], "poses": [
    {"position": {"x": 1, "y": 2, "z": 0.8}, "orientation": {"x": 0, "y": 0, "z": 0, "w": 1}},
    {"position": {"x": null, "y": 2, "z": 0.8}, "orientation": {"x": 0, "y": 0, "z": 0, "w": 1}}]},
  {"type": "Knife", "id": 3, "path": [], "poses": []}]})";

TEST(Documents, ReadsThePredictOutputNullAsNaN) {
  TempDir dir("nbv_documents");
  const auto clouds = readPredictedClouds(write(dir, "clouds.json", kPrediction));
  ASSERT_EQ(clouds.size(), 2u);
  EXPECT_EQ(clouds[0].key.type, "Cup");
  EXPECT_EQ(clouds[0].key.id, "0");
  ASSERT_EQ(clouds[0].poses.size(), 2u);
  EXPECT_EQ(clouds[0].poses[0].position, Eigen::Vector3d(1, 2, 0.8));
  EXPECT_TRUE(std::isnan(clouds[0].poses[1].position.x()));
  EXPECT_EQ(clouds[1].key.id, "3");
  EXPECT_TRUE(clouds[1].poses.empty());
  // The NaN pose is rejected and counted when hypotheses are made.
  const HypothesisSet set(clouds, {});
  EXPECT_EQ(set.hypotheses().size(), 1u);
  EXPECT_EQ(set.rejectedPoses(), 1);
}

TEST(Documents, ReadsAListOfPredictOutputs) {
  TempDir dir("nbv_documents");
  const auto clouds = readPredictedClouds(
      write(dir, "clouds.json", std::string("[") + kPrediction + "," + kPrediction + "]"));
  EXPECT_EQ(clouds.size(), 4u);
}

TEST(Documents, MalformedCloudsNameTheFileAndTheField) {
  TempDir dir("nbv_documents");
  const std::string path =
      write(dir, "bad.json", R"({"predictions": [{"type": "Cup", "poses": [{"position": 1}]}]})");
  try {
    readPredictedClouds(path);
    FAIL() << "no error";
  } catch (const asr_common::InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("bad.json"), std::string::npos) << message;
    EXPECT_NE(message.find("predictions[0].poses[0]"), std::string::npos) << message;
  }
  EXPECT_THROW(readPredictedClouds(write(dir, "other.json", R"({"scenes": []})")),
               asr_common::InputError);
  EXPECT_THROW(readPredictedClouds(dir.file("missing.json")), asr_common::InputError);
}

TEST(Documents, ReadsVisitedViewsAndRefusesAnUnnormalisedQuaternion) {
  TempDir dir("nbv_documents");
  const auto views = readVisitedViews(write(dir, "visited.json", R"([
    {"camera": {"position": {"x": 1, "y": 1, "z": 1.3},
                "orientation": {"x": 0, "y": 0, "z": 0, "w": 1}}, "types": ["Cup", "Knife"]}])"));
  ASSERT_EQ(views.size(), 1u);
  EXPECT_EQ(views[0].types, (std::vector<std::string>{"Cup", "Knife"}));
  EXPECT_THROW(readVisitedViews(write(dir, "bad.json", R"([
    {"camera": {"position": {"x": 1, "y": 1, "z": 1.3},
                "orientation": {"x": 0, "y": 0, "z": 0, "w": 2}}, "types": []}])")),
               asr_common::InputError);
}

}  // namespace
}  // namespace asr_nbv
