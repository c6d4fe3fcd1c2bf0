#include "asr_robot_model/tag_map.hpp"

#include <cmath>

#include "asr_robot_model/document.hpp"
#include "asr_robot_model/shipped_files.hpp"
#include "asr_robot_model/tag_family.hpp"

namespace asr_robot_model {
namespace {

int tagId(const Field& field) {
  const double id = field.number();
  if (id < 0 || id != std::floor(id) || id > 1e6)
    field.fail("must be a non-negative whole number");
  return static_cast<int>(id);
}

TagPlacement readPlacement(const Field& field) {
  TagPlacement tag;
  tag.id = tagId(field["id"]);
  tag.object = {field["object"]["type"].text(), field["object"]["id"].text()};
  if (tag.object.type.empty())
    field["object"]["type"].fail("must not be empty");
  tag.edge_length = field["edge_length"].number();
  if (tag.edge_length <= 0.0)
    field["edge_length"].fail("must be positive (metres)");
  const Field pose = field["pose"];
  tag.pose = asr_common::Pose(pose["position"].position(), pose["orientation"].orientation());
  return tag;
}

}  // namespace

const TagPlacement* TagMap::find(int id) const {
  const auto found = tags.find(id);
  return found == tags.end() ? nullptr : &found->second;
}

TagMap loadTagMap(const std::string& path) {
  const nlohmann::json document = readDocument(path);
  const Field root(document, path, "");
  if (root["version"].number() != 1.0)
    root["version"].fail("only version 1 is known");
  TagMap map;
  if (root.has("family"))
    map.family = root["family"].text();
  if (!isKnownTagFamily(map.family))
    root["family"].fail("'" + map.family +
                        "' is not a known family (tag36h11, tag25h9, tag16h5, tagStandard41h12, "
                        "tagStandard52h13)");
  const Field tags = root["tags"];
  if (tags.size() == 0)
    tags.fail("must list at least one tag");
  for (std::size_t i = 0; i < tags.size(); ++i) {
    const TagPlacement tag = readPlacement(tags[i]);
    if (!map.tags.emplace(tag.id, tag).second)
      tags[i]["id"].fail("tag " + std::to_string(tag.id) + " is listed twice");
  }
  return map;
}

std::string defaultTagMap() {
  return shippedFile("config/tag_map.yaml");
}

}  // namespace asr_robot_model
