#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "asr_ism/demonstration.hpp"
#include "asr_ism/ism_recognizer.hpp"
#include "asr_ism_tree/relation_topology.hpp"

namespace asr_ism_tree {

/// Which relations each of a set of configurations breaks. The deficit of the relation between
/// objects a and b in a configuration that shows both is 1 - the best similarity (the ISM's
/// position compliance times orientation compliance) of their relative pose to one demonstrated
/// for the pair; the relation is broken if the deficit exceeds `max_deficit`. A tree that models a
/// broken relation will most likely reject the configuration, so the configurations a topology
/// accepts can be predicted without learning its tree: the search uses this to try the most
/// promising neighbours first (it still evaluates every one for real).
class RelationViolations {
 public:
  RelationViolations(const asr_ism::Demonstration& demonstration,
                     const std::vector<asr_common::Configuration>& configurations,
                     const asr_ism::IsmRecognitionParameters& parameters, double max_deficit);

  std::size_t configurationCount() const { return configuration_count_; }

  bool breaks(std::size_t configuration, std::size_t a, std::size_t b) const;

  /// How many of the configurations break none of the topology's relations.
  std::size_t predictedAccepted(const RelationTopology& topology) const;

 private:
  using Bits = std::vector<std::uint64_t>;
  const Bits& bitsOf(std::size_t a, std::size_t b) const;

  std::size_t object_count_ = 0;
  std::size_t configuration_count_ = 0;
  std::vector<Bits> broken_;  // per object pair (a < b), one bit per configuration
};

/// `start` with relations added greedily, each the one that catches (breaks in) the most
/// configurations no relation added so far catches, until none catches another or the tree would
/// grow higher than `max_height` (no limit if < 1). Ties go to the first pair in object order.
RelationTopology withCatchingRelations(const RelationTopology& start,
                                       const RelationViolations& violations, int max_height);

}  // namespace asr_ism_tree
