#include "asr_robot_model/document.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "asr_common/input_error.hpp"

namespace asr_robot_model {
namespace {

using asr_common::InputError;

nlohmann::json scalarToJson(const YAML::Node& node) {
  const std::string& text = node.Scalar();
  if (node.Tag() == "!")  // quoted: a string, even "0"
    return text;
  if (text == "true" || text == "false")
    return text == "true";
  if (text == "null" || text == "~")
    return nullptr;
  double number = 0.0;
  if (YAML::convert<double>::decode(node, number))
    return number;
  return text;
}

nlohmann::json yamlToJson(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Sequence: {
      nlohmann::json list = nlohmann::json::array();
      for (const YAML::Node& item : node)
        list.push_back(yamlToJson(item));
      return list;
    }
    case YAML::NodeType::Map: {
      nlohmann::json map = nlohmann::json::object();
      for (const auto& entry : node)
        map[entry.first.Scalar()] = yamlToJson(entry.second);
      return map;
    }
    case YAML::NodeType::Scalar:
      return scalarToJson(node);
    default:
      return nullptr;
  }
}

bool endsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

nlohmann::json readDocument(const std::string& path) {
  std::ifstream file(path);
  if (!file)
    throw InputError(path + ": cannot read the file");
  std::stringstream content;
  content << file.rdbuf();
  try {
    if (endsWith(path, ".json"))
      return nlohmann::json::parse(content.str());
    return yamlToJson(YAML::Load(content.str()));
  } catch (const nlohmann::json::exception& error) {
    throw InputError(path + ": not valid JSON: " + error.what());
  } catch (const YAML::Exception& error) {
    throw InputError(path + ": not valid YAML: " + error.what());
  }
}

Field::Field(const nlohmann::json& node, std::string file, std::string path)
    : node_(&node), file_(std::move(file)), path_(std::move(path)) {}

void Field::fail(const std::string& problem) const {
  throw InputError(file_ + ": " + (path_.empty() ? "document" : path_) + ": " + problem);
}

bool Field::has(const std::string& key) const {
  return node_->is_object() && node_->find(key) != node_->end();
}

Field Field::operator[](const std::string& key) const {
  const std::string child = path_.empty() ? key : path_ + "." + key;
  if (!node_->is_object())
    fail("must be a map");
  const auto found = node_->find(key);
  if (found == node_->end())
    Field(*node_, file_, child).fail("missing");
  return Field(*found, file_, child);
}

Field Field::operator[](std::size_t index) const {
  return Field(node_->at(index), file_, path_ + "[" + std::to_string(index) + "]");
}

std::size_t Field::size() const {
  if (node_->is_null())
    return 0;
  if (!node_->is_array())
    fail("must be a list");
  return node_->size();
}

std::vector<std::string> Field::keys() const {
  if (!node_->is_object())
    fail("must be a map");
  std::vector<std::string> names;
  for (const auto& entry : node_->items())
    names.push_back(entry.key());
  return names;
}

double Field::number() const {
  if (!node_->is_number() || !std::isfinite(node_->get<double>()))
    fail("must be a finite number");
  return node_->get<double>();
}

std::string Field::text() const {
  if (node_->is_string())
    return node_->get<std::string>();
  // An unquoted id such as 0 reads as a number; an integral one is taken as its digits.
  if (node_->is_number() && std::isfinite(node_->get<double>()) &&
      node_->get<double>() == std::floor(node_->get<double>()) &&
      std::abs(node_->get<double>()) < 1e15)
    return std::to_string(static_cast<long long>(node_->get<double>()));
  fail("must be a text");
}

Eigen::Vector3d Field::vector3() const {
  if (size() != 3)
    fail("must be a list of 3 numbers");
  return {(*this)[0].number(), (*this)[1].number(), (*this)[2].number()};
}

Eigen::Vector3d Field::position() const {
  return {(*this)["x"].number(), (*this)["y"].number(), (*this)["z"].number()};
}

Eigen::Quaterniond Field::orientation() const {
  const Eigen::Quaterniond q((*this)["w"].number(), (*this)["x"].number(), (*this)["y"].number(),
                             (*this)["z"].number());
  if (std::abs(q.norm() - 1.0) > 1e-3)
    fail("must be a unit quaternion (norm " + std::to_string(q.norm()) + ")");
  return q.normalized();
}

}  // namespace asr_robot_model
