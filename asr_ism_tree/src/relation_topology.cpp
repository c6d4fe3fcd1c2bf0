#include "asr_ism_tree/relation_topology.hpp"

#include <algorithm>
#include <stdexcept>

#include "asr_common/input_error.hpp"

namespace asr_ism_tree {

using asr_common::InputError;

RelationTopology::RelationTopology(std::vector<ObjectKey> objects)
    : objects_(std::move(objects)), adjacency_(objects_.size() * objects_.size(), 0) {
  std::vector<ObjectKey> sorted = objects_;
  std::sort(sorted.begin(), sorted.end());
  const auto duplicate = std::adjacent_find(sorted.begin(), sorted.end());
  if (duplicate != sorted.end()) {
    throw InputError("relation topology: object " + duplicate->toString() + " is listed twice");
  }
}

RelationTopology RelationTopology::star(std::vector<ObjectKey> objects, std::size_t center) {
  RelationTopology topology(std::move(objects));
  if (center >= topology.objectCount()) {
    throw std::out_of_range("star centre index out of range");
  }
  for (std::size_t other = 0; other < topology.objectCount(); ++other) {
    if (other != center)
      topology.addRelation(center, other);
  }
  return topology;
}

RelationTopology RelationTopology::complete(std::vector<ObjectKey> objects) {
  RelationTopology topology(std::move(objects));
  for (std::size_t a = 0; a < topology.objectCount(); ++a) {
    for (std::size_t b = a + 1; b < topology.objectCount(); ++b)
      topology.addRelation(a, b);
  }
  return topology;
}

int RelationTopology::indexOf(const ObjectKey& key) const {
  const auto found = std::find(objects_.begin(), objects_.end(), key);
  return found == objects_.end() ? -1 : static_cast<int>(found - objects_.begin());
}

void RelationTopology::addRelation(std::size_t a, std::size_t b) {
  if (a >= objectCount() || b >= objectCount() || a == b) {
    throw std::out_of_range("relation between invalid object indices");
  }
  if (!adjacency_[a * objectCount() + b]) {
    adjacency_[a * objectCount() + b] = adjacency_[b * objectCount() + a] = 1;
    ++relation_count_;
  }
}

void RelationTopology::removeRelation(std::size_t a, std::size_t b) {
  if (hasRelation(a, b)) {
    adjacency_[a * objectCount() + b] = adjacency_[b * objectCount() + a] = 0;
    --relation_count_;
  }
}

bool RelationTopology::hasRelation(std::size_t a, std::size_t b) const {
  return a < objectCount() && b < objectCount() && adjacency_[a * objectCount() + b] != 0;
}

std::vector<std::pair<int, int>> RelationTopology::relations() const {
  std::vector<std::pair<int, int>> result;
  for (std::size_t a = 0; a < objectCount(); ++a) {
    for (std::size_t b = a + 1; b < objectCount(); ++b) {
      if (hasRelation(a, b))
        result.emplace_back(static_cast<int>(a), static_cast<int>(b));
    }
  }
  return result;
}

std::size_t RelationTopology::degree(std::size_t object) const {
  return neighbours(object).size();
}

std::vector<int> RelationTopology::neighbours(std::size_t object) const {
  std::vector<int> result;
  for (std::size_t other = 0; other < objectCount(); ++other) {
    if (hasRelation(object, other))
      result.push_back(static_cast<int>(other));
  }
  return result;
}

std::vector<char> RelationTopology::reachableFrom(std::size_t start) const {
  std::vector<char> reached(objectCount(), 0);
  std::vector<int> frontier = {static_cast<int>(start)};
  reached[start] = 1;
  while (!frontier.empty()) {
    const int current = frontier.back();
    frontier.pop_back();
    for (int next : neighbours(current)) {
      if (!reached[next]) {
        reached[next] = 1;
        frontier.push_back(next);
      }
    }
  }
  return reached;
}

bool RelationTopology::isConnected() const {
  if (objects_.empty())
    return false;
  const std::vector<char> reached = reachableFrom(0);
  return std::all_of(reached.begin(), reached.end(), [](char r) { return r != 0; });
}

void RelationTopology::requireConnected(const std::string& what) const {
  if (objects_.empty()) {
    throw InputError(what + ": the relation topology has no object");
  }
  // Name the objects that the first object cannot reach, so the user sees what is cut off.
  const std::vector<char> reached = reachableFrom(0);
  std::string unreachable;
  for (std::size_t object = 0; object < objectCount(); ++object) {
    if (!reached[object]) {
      unreachable += (unreachable.empty() ? "" : ", ") + objects_[object].toString();
    }
  }
  if (unreachable.empty())
    return;
  throw InputError(what + ": the relation topology is not connected; " + unreachable +
                   " cannot be reached from " + objects_[0].toString());
}

}  // namespace asr_ism_tree
