#pragma once

#include <vector>

#include "asr_ism_tree/relation_topology.hpp"

namespace asr_ism_tree {

/// Height of the ISM tree that generateIsmTree builds from a connected topology (1 for a star).
int treeHeightOf(const RelationTopology& topology);

/// The neighbours of a topology in the local search: every topology that differs by adding one
/// relation, removing one, or exchanging one for one not present; only connected ones whose tree
/// height is at most `max_height` (no limit if < 1). In a fixed order: additions, removals, then
/// exchanges, each by ascending relation.
std::vector<RelationTopology> topologyNeighbours(const RelationTopology& topology, int max_height);

}  // namespace asr_ism_tree
