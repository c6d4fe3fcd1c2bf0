#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "asr_common/object.hpp"

namespace asr_ism_tree {

using asr_common::ObjectKey;

/// An undirected graph over a scene's objects whose edges are the spatial relations an ISM tree
/// models. A value type: copy it, compare it, modify it.
class RelationTopology {
 public:
  RelationTopology() = default;
  /// A topology over these objects without any relation. Throws InputError for duplicates.
  explicit RelationTopology(std::vector<ObjectKey> objects);

  /// Every object related to `center` only.
  static RelationTopology star(std::vector<ObjectKey> objects, std::size_t center);
  /// Every pair of objects related.
  static RelationTopology complete(std::vector<ObjectKey> objects);

  const std::vector<ObjectKey>& objects() const { return objects_; }
  std::size_t objectCount() const { return objects_.size(); }
  /// Index of an object, or -1.
  int indexOf(const ObjectKey& key) const;

  void addRelation(std::size_t a, std::size_t b);
  void removeRelation(std::size_t a, std::size_t b);
  bool hasRelation(std::size_t a, std::size_t b) const;
  std::size_t relationCount() const { return relation_count_; }
  /// All relations as (a, b) with a < b, sorted.
  std::vector<std::pair<int, int>> relations() const;
  std::size_t degree(std::size_t object) const;
  /// Related objects of `object`, in index order.
  std::vector<int> neighbours(std::size_t object) const;

  /// True if every object can be reached from every other through relations (a single object is
  /// connected).
  bool isConnected() const;
  /// Throws InputError naming `what` and the unreachable objects if the topology is not connected.
  void requireConnected(const std::string& what) const;

  friend bool operator==(const RelationTopology& a, const RelationTopology& b) {
    return a.objects_ == b.objects_ && a.adjacency_ == b.adjacency_;
  }
  friend bool operator!=(const RelationTopology& a, const RelationTopology& b) { return !(a == b); }

 private:
  std::vector<char> reachableFrom(std::size_t start) const;

  std::vector<ObjectKey> objects_;
  std::vector<std::uint8_t> adjacency_;  // objectCount x objectCount, symmetric
  std::size_t relation_count_ = 0;
};

}  // namespace asr_ism_tree
