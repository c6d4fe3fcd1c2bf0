#pragma once

#include <vector>

#include "asr_ism_tree/relation_topology.hpp"

namespace asr_ism_tree {

/// A star-shaped part of a relation topology: a centre related to each of its neighbours.
struct Star {
  int center = -1;
  std::vector<int> neighbours;  // object indices, ascending
  /// Distance from the root star in the graph where star k may be the parent of star j when j's
  /// centre is one of k's neighbours; the paper's height function. 0 for the root star.
  int height = 0;
  /// The star whose neighbour `center` this star's ISM replaces: the first star (in extraction
  /// order) one height closer to the root that has `center` as a neighbour. -1 for the root.
  int parent = -1;
};

/// Partitions a connected topology into stars by a depth-first search that starts at the object
/// of highest degree (or at `root_center` if >= 0) and always continues with the neighbour that
/// has the most relations left; each visited object becomes the centre of a star holding all its
/// relations not yet taken. Ties go to the lower object index. Every relation ends up in exactly
/// one star. A topology of one object yields one star without neighbours.
/// Throws InputError if the topology is not connected.
std::vector<Star> partitionIntoStars(const RelationTopology& topology, int root_center = -1);

}  // namespace asr_ism_tree
