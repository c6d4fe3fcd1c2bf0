#include "asr_ism/configuration_file.hpp"

#include <yaml-cpp/yaml.h>

#include <sys/stat.h>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <limits>
#include <set>
#include <sstream>

#include "asr_common/atomic_file.hpp"
#include "asr_ism/common_types.hpp"

namespace asr_ism {
namespace {

double numberField(const YAML::Node& parent, const char* field, const std::string& what) {
  const YAML::Node node = parent[field];
  if (!node)
    throw InputError(what + ": field '" + field + "' is missing");
  if (!node.IsScalar())
    throw InputError(what + ": field '" + field + "' is not a number");
  try {
    return node.as<double>();
  } catch (const YAML::Exception&) {
    throw InputError(what + ": field '" + field + "' is not a number ('" + node.Scalar() + "')");
  }
}

// A quaternion component: one left out is 0, as in a ROS message (so `{z: 0.38, w: 0.92}` is a
// turn about z); an all-zero quaternion is still refused by validatedPose, naming the object.
double quaternionComponent(const YAML::Node& orientation, const char* field,
                           const std::string& what) {
  return orientation[field] ? numberField(orientation, field, what) : 0.0;
}

YAML::Node mapField(const YAML::Node& parent, const char* field, const std::string& what) {
  const YAML::Node node = parent[field];
  if (!node)
    throw InputError(what + ": field '" + field + "' is missing");
  if (!node.IsMap())
    throw InputError(what + ": field '" + field + "' is not a mapping");
  return node;
}

ObjectEstimate readObject(const YAML::Node& node, const std::string& what) {
  if (!node.IsMap())
    throw InputError(what + ": is not a mapping with type, id and pose");
  ObjectEstimate estimate;
  const YAML::Node type = node["type"];
  if (!type || !type.IsScalar() || type.Scalar().empty()) {
    throw InputError(what + ": field 'type' is missing or empty");
  }
  estimate.key.type = type.Scalar();
  const YAML::Node id = node["id"];
  if (id) {
    if (!id.IsScalar())
      throw InputError(what + ": field 'id' is not a scalar");
    estimate.key.id = id.Scalar();
  }
  const std::string named = what + " (" + estimate.key.toString() + ")";
  const YAML::Node pose = mapField(node, "pose", named);
  const YAML::Node position = mapField(pose, "position", named + " pose");
  const YAML::Node orientation = mapField(pose, "orientation", named + " pose");
  const std::string in_orientation = named + " orientation";
  const Eigen::Quaterniond quaternion(quaternionComponent(orientation, "w", in_orientation),
                                      quaternionComponent(orientation, "x", in_orientation),
                                      quaternionComponent(orientation, "y", in_orientation),
                                      quaternionComponent(orientation, "z", in_orientation));
  estimate.pose = validatedPose(Eigen::Vector3d(numberField(position, "x", named + " position"),
                                                numberField(position, "y", named + " position"),
                                                numberField(position, "z", named + " position")),
                                quaternion, named);
  return estimate;
}

// yaml-cpp keeps a key given twice and answers lookups with one of them: which value a user
// meant is unknowable, so the file is refused.
void rejectDuplicateKeys(const YAML::Node& node, const std::string& path) {
  if (node.IsSequence()) {
    for (const YAML::Node& element : node)
      rejectDuplicateKeys(element, path);
    return;
  }
  if (!node.IsMap())
    return;
  std::set<std::string> keys;
  for (const auto& entry : node) {
    const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : YAML::Dump(entry.first);
    if (!keys.insert(key).second) {
      throw InputError(path + ": line " + std::to_string(entry.first.Mark().line + 1) + ": key '" +
                       key + "' is given twice");
    }
    rejectDuplicateKeys(entry.second, path);
  }
}

// YAML double-quoted scalar, so any type or id text survives the round trip. Control characters
// are escaped: a line break written as it is would be read back as a space.
std::string quoted(const std::string& text) {
  std::string result = "\"";
  for (char c : text) {
    const auto code = static_cast<unsigned char>(c);
    if (code < 0x20 || code == 0x7f) {
      char escape[5];
      std::snprintf(escape, sizeof escape, "\\x%02x", code);
      result += escape;
      continue;
    }
    if (c == '"' || c == '\\')
      result += '\\';
    result += c;
  }
  return result + "\"";
}

}  // namespace

Configuration readConfigurationFile(const std::string& path) {
  std::ifstream file(path);
  if (!file)
    throw InputError(path + ": cannot open the objects file");
  std::vector<YAML::Node> documents;
  try {
    documents = YAML::LoadAll(file);
  } catch (const YAML::ParserException& error) {
    throw InputError(path + ": malformed YAML/JSON at line " + std::to_string(error.mark.line + 1) +
                     ": " + error.msg);
  } catch (const std::ios_base::failure& error) {
    // E.g. a folder: it opens, but reading it fails.
    throw InputError(path + ": cannot read the objects file (" + error.what() + ")");
  }
  // Text after the mapping (`{...} garbage`, a second document) would be ignored silently.
  if (documents.size() > 1) {
    throw InputError(path + ": unexpected content after the objects at line " +
                     std::to_string(documents[1].Mark().line + 1));
  }
  const YAML::Node root = documents.empty() ? YAML::Node() : documents.front();
  rejectDuplicateKeys(root, path);
  if (!root.IsMap() || !root["objects"]) {
    throw InputError(path + ": expected a mapping with a list 'objects'");
  }
  const YAML::Node objects = root["objects"];
  if (!objects.IsSequence())
    throw InputError(path + ": 'objects' is not a list");
  Configuration configuration;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    configuration.push_back(readObject(objects[i], path + ": object " + std::to_string(i)));
  }
  return configuration;
}

void writeConfigurationFile(const std::string& path, const Configuration& configuration,
                            bool overwrite) {
  struct stat info;
  if (!overwrite && stat(path.c_str(), &info) == 0) {
    throw InputError(path + ": exists already; not overwritten");
  }
  std::ostringstream text;
  text << std::setprecision(std::numeric_limits<double>::max_digits10);
  // An empty list must be written as one: a bare "objects:" would read back as null.
  text << (configuration.empty() ? "objects: []\n" : "objects:\n");
  for (const ObjectEstimate& estimate : configuration) {
    const Pose& pose = estimate.pose;
    text << "  - type: " << quoted(estimate.key.type) << "\n"
         << "    id: " << quoted(estimate.key.id) << "\n"
         << "    pose:\n"
         << "      position: {x: " << pose.position.x() << ", y: " << pose.position.y()
         << ", z: " << pose.position.z() << "}\n"
         << "      orientation: {x: " << pose.orientation.x() << ", y: " << pose.orientation.y()
         << ", z: " << pose.orientation.z() << ", w: " << pose.orientation.w() << "}\n";
  }
  asr_common::writeFileAtomically(path, text.str());
}

}  // namespace asr_ism
