#pragma once

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace asr_robot_model {

/// Reads a YAML or JSON file (JSON if its name ends in .json, else YAML, of which JSON is a
/// subset) into one JSON tree, so worlds and catalogues have one reader. Quoted YAML scalars stay
/// strings; plain ones become numbers or booleans where they read as such. Throws
/// asr_common::InputError naming the file if it cannot be read or parsed.
nlohmann::json readDocument(const std::string& path);

/// One field of a document, for reading with errors that name the file and the field
/// ("world.yaml: objects[2].pose.position.x: must be a number").
class Field {
 public:
  Field(const nlohmann::json& node, std::string file, std::string path);

  bool has(const std::string& key) const;
  Field operator[](const std::string& key) const;  // required member
  Field operator[](std::size_t index) const;
  std::size_t size() const;               // of a list (an absent field is an empty list)
  std::vector<std::string> keys() const;  // of a map

  double number() const;
  std::string text() const;
  Eigen::Vector3d vector3() const;         // [x, y, z]
  Eigen::Vector3d position() const;        // {x, y, z}
  Eigen::Quaterniond orientation() const;  // {x, y, z, w}, unnormalised refused

  [[noreturn]] void fail(const std::string& problem) const;
  const std::string& path() const { return path_; }

 private:
  const nlohmann::json* node_;
  std::string file_;
  std::string path_;
};

}  // namespace asr_robot_model
