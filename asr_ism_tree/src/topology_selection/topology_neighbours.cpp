#include "asr_ism_tree/topology_selection/topology_neighbours.hpp"

#include <algorithm>

#include "asr_ism_tree/star_partition.hpp"

namespace asr_ism_tree {

int treeHeightOf(const RelationTopology& topology) {
  int height = 0;
  for (const Star& star : partitionIntoStars(topology))
    height = std::max(height, star.height);
  return height + 1;
}

std::vector<RelationTopology> topologyNeighbours(const RelationTopology& topology, int max_height) {
  const std::size_t n = topology.objectCount();
  std::vector<std::pair<int, int>> present;
  std::vector<std::pair<int, int>> absent;
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b)
      (topology.hasRelation(a, b) ? present : absent).push_back({int(a), int(b)});
  }
  std::vector<RelationTopology> candidates;
  for (const auto& [a, b] : absent) {
    RelationTopology added = topology;
    added.addRelation(a, b);
    candidates.push_back(std::move(added));
  }
  for (const auto& [a, b] : present) {
    RelationTopology removed = topology;
    removed.removeRelation(a, b);
    candidates.push_back(std::move(removed));
  }
  for (const auto& [a, b] : present) {
    for (const auto& [c, d] : absent) {
      RelationTopology exchanged = topology;
      exchanged.removeRelation(a, b);
      exchanged.addRelation(c, d);
      candidates.push_back(std::move(exchanged));
    }
  }
  std::vector<RelationTopology> neighbours;
  for (RelationTopology& candidate : candidates) {
    if (!candidate.isConnected())
      continue;
    if (max_height >= 1 && treeHeightOf(candidate) > max_height)
      continue;
    neighbours.push_back(std::move(candidate));
  }
  return neighbours;
}

}  // namespace asr_ism_tree
