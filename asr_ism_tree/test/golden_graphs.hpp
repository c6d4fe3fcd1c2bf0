#pragma once

// Small relation topologies whose star partitions and ISM trees the tests work out by hand.

#include <string>
#include <vector>

#include "asr_ism_tree/relation_topology.hpp"

namespace asr_ism_tree::golden {

// Objects A, B, C, ... with an instance id, so keys print as "A:1".
inline std::vector<ObjectKey> lettered(int count) {
  std::vector<ObjectKey> keys;
  for (int i = 0; i < count; ++i)
    keys.push_back({std::string(1, static_cast<char>('A' + i)), "1"});
  return keys;
}

inline RelationTopology withRelations(int count, const std::vector<std::pair<int, int>>& pairs) {
  RelationTopology topology(lettered(count));
  for (const auto& [a, b] : pairs)
    topology.addRelation(a, b);
  return topology;
}

// A - B - C - D
inline RelationTopology chain() {
  return withRelations(4, {{0, 1}, {1, 2}, {2, 3}});
}
// A - B - C - A
inline RelationTopology triangle() {
  return withRelations(3, {{0, 1}, {1, 2}, {0, 2}});
}
// every pair of A, B, C, D
inline RelationTopology complete4() {
  return RelationTopology::complete(lettered(4));
}
// C related to A, B and D
inline RelationTopology starAroundC() {
  return RelationTopology::star(lettered(4), 2);
}
// C is the hub (A, D, E, F); A - B - D closes a loop through B, so B ends up two stars down.
inline RelationTopology branching() {
  return withRelations(6, {{0, 1}, {0, 2}, {1, 3}, {2, 3}, {2, 4}, {2, 5}});
}

}  // namespace asr_ism_tree::golden
