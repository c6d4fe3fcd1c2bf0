// Tag maps: the shipped kitchen map reads and every tag sits flat on a face of its object's box,
// facing out; malformed maps are refused with the file and the field named.
#include <gtest/gtest.h>

#include <string>

#include "asr_common/testing/input_error_of.hpp"
#include "asr_common/testing/temp_dir.hpp"
#include "asr_robot_model/tag_map.hpp"
#include "asr_robot_model/world.hpp"
#include "refused_edit.hpp"

using asr_common::testing::inputErrorOf;
using asr_common::testing::TempDir;
using namespace asr_robot_model;

namespace {

const char* const kValid = R"(version: 1
family: tag36h11
tags:
  - id: 3
    object: {type: Cup, id: "0"}
    edge_length: 0.05
    pose: {position: {x: 0.045, y: 0, z: 0}, orientation: {x: 0.5, y: 0.5, z: 0.5, w: 0.5}}
  - id: 7
    object: {type: Cup, id: "0"}
    edge_length: 0.04
    pose: {position: {x: -0.045, y: 0, z: 0}, orientation: {x: 0.5, y: -0.5, z: -0.5, w: 0.5}}
)";

void expectRefused(const std::string& from, const std::string& to, const std::string& field) {
  asr_robot_model::testing::expectEditRefused(TempDir("tag_map"), "tags.yaml", kValid, from, to,
                                              field,
                                              [](const std::string& path) { loadTagMap(path); });
}

}  // namespace

TEST(TagMap, ReadsSeveralTagsOfOneObject) {
  TempDir dir("tag_map");
  const TagMap map = loadTagMap(dir.write("tags.yaml", kValid));
  EXPECT_EQ(map.family, "tag36h11");
  ASSERT_EQ(map.tags.size(), 2u);
  ASSERT_NE(map.find(7), nullptr);
  EXPECT_EQ(map.find(7)->object, (asr_common::ObjectKey{"Cup", "0"}));
  EXPECT_DOUBLE_EQ(map.find(7)->edge_length, 0.04);
  EXPECT_EQ(map.find(3)->pose.position, Eigen::Vector3d(0.045, 0, 0));
  EXPECT_EQ(map.find(5), nullptr);
}

TEST(TagMap, FamilyDefaultsToTag36h11) {
  TempDir dir("tag_map");
  std::string text = kValid;
  text.erase(text.find("family: tag36h11\n"), 17);
  EXPECT_EQ(loadTagMap(dir.write("tags.yaml", text)).family, "tag36h11");
}

// Each shipped tag lies on a face of its object's catalogue box, its z along that face's
// outward normal, and the printed tag (with its white margin) fits on the face.
TEST(TagMap, ShippedTagsLieFlatOnTheirObjectsFaces) {
  const TagMap map = loadTagMap(defaultTagMap());
  const ObjectCatalogue catalogue = loadObjectCatalogue(defaultObjectCatalogue());
  ASSERT_GE(map.tags.size(), 8u);
  for (const auto& [id, tag] : map.tags) {
    SCOPED_TRACE("tag " + std::to_string(id));
    ASSERT_EQ(catalogue.count(tag.object.type), 1u);
    const Eigen::Vector3d half = catalogue.at(tag.object.type).size / 2.0;
    const Eigen::Matrix3d rotation = tag.pose.orientation.toRotationMatrix();
    const Eigen::Vector3d normal = rotation.col(2);
    int axis = 0;
    normal.cwiseAbs().maxCoeff(&axis);
    EXPECT_NEAR(std::abs(normal[axis]), 1.0, 1e-6);
    EXPECT_NEAR(tag.pose.position[axis], (normal[axis] > 0 ? 1 : -1) * half[axis], 1e-9);
    const double printed_half = tag.edge_length * 10.0 / 8.0 / 2.0;  // tag36h11's margin
    for (const int in_plane : {0, 1}) {
      const Eigen::Vector3d edge = rotation.col(in_plane).cwiseAbs();
      int along = 0;
      edge.maxCoeff(&along);
      EXPECT_LE(std::abs(tag.pose.position[along]) + printed_half, half[along] + 1e-9);
    }
  }
}

TEST(TagMap, MalformedMapsNameTheFileAndField) {
  expectRefused("version: 1", "version: 2", "version");
  expectRefused("family: tag36h11", "family: tag99h1", "family");
  expectRefused("id: 7", "id: 3", "tags[1].id");
  expectRefused("id: 7", "id: -1", "tags[1].id");
  expectRefused("id: 7", "id: 2.5", "tags[1].id");
  expectRefused("edge_length: 0.04", "edge_length: 0", "tags[1].edge_length");
  expectRefused("edge_length: 0.04", "edge_length: .nan", "tags[1].edge_length");
  expectRefused("object: {type: Cup, id: \"0\"}\n    edge_length: 0.04", "edge_length: 0.04",
                "tags[1].object");
  expectRefused("w: 0.5}}\n  - id: 7", "w: 0.9}}\n  - id: 7", "tags[0].pose.orientation");
  expectRefused("x: -0.045", "x: abc", "tags[1].pose.position.x");
}

TEST(TagMap, MissingFileIsNamed) {
  const std::string message = inputErrorOf([] { loadTagMap("/nonexistent/tags.yaml"); });
  EXPECT_NE(message.find("/nonexistent/tags.yaml"), std::string::npos) << message;
}
