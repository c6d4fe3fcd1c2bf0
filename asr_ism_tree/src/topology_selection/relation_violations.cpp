#include "asr_ism_tree/topology_selection/relation_violations.hpp"

#include <algorithm>
#include <bitset>
#include <cmath>

#include "asr_ism/compliance.hpp"

#include "asr_ism_tree/topology_selection/topology_neighbours.hpp"

namespace asr_ism_tree {
namespace {

// Index of the unordered pair a != b among the n(n-1)/2 pairs.
std::size_t pairIndex(std::size_t a, std::size_t b, std::size_t n) {
  if (a > b)
    std::swap(a, b);
  return a * n - a * (a + 1) / 2 + (b - a - 1);
}

}  // namespace

RelationViolations::RelationViolations(const asr_ism::Demonstration& demonstration,
                                       const std::vector<asr_common::Configuration>& configurations,
                                       const asr_ism::IsmRecognitionParameters& parameters,
                                       double max_deficit)
    : object_count_(demonstration.objectCount()), configuration_count_(configurations.size()) {
  const std::size_t n = object_count_;
  const std::size_t words = (configuration_count_ + 63) / 64;
  broken_.assign(n * (n - 1) / 2, Bits(words, 0));
  const double max_distance_squared = parameters.bin_size * parameters.bin_size;
  const double sin_half_squared_max =
      asr_ism::sinHalfSquared(std::cos(0.5 * parameters.max_angle_deviation));

  // Each configuration's poses by object index (nullptr where the object is absent).
  std::vector<std::vector<const asr_common::Pose*>> poses(configurations.size(),
                                                          std::vector<const asr_common::Pose*>(n));
  for (std::size_t c = 0; c < configurations.size(); ++c) {
    for (const asr_common::ObjectEstimate& estimate : configurations[c]) {
      const int index = demonstration.indexOf(estimate.key);
      if (index >= 0)
        poses[c][index] = &estimate.pose;
    }
  }
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      std::vector<asr_common::Pose> demonstrated;
      for (std::size_t step = 0; step < demonstration.stepCount(); ++step) {
        if (demonstration.pose(step, a) && demonstration.pose(step, b))
          demonstrated.push_back(
              asr_common::relativePose(*demonstration.pose(step, a), *demonstration.pose(step, b)));
      }
      Bits& bits = broken_[pairIndex(a, b, n)];
      for (std::size_t c = 0; c < configurations.size(); ++c) {
        if (!poses[c][a] || !poses[c][b])
          continue;  // a relation to an absent object cannot be broken
        // Comparing relative poses in a's frame is comparing where b is against where the
        // relation puts it: the rotation into a's frame keeps distances and angles.
        const asr_common::Pose seen = asr_common::relativePose(*poses[c][a], *poses[c][b]);
        double best = 0.0;
        for (const asr_common::Pose& relative : demonstrated) {
          const double similarity =
              asr_ism::positionCompliance((relative.position - seen.position).squaredNorm(),
                                          max_distance_squared) *
              asr_ism::orientationCompliance(std::abs(relative.orientation.dot(seen.orientation)),
                                             sin_half_squared_max);
          best = std::max(best, similarity);
        }
        if (1.0 - best > max_deficit)
          bits[c / 64] |= std::uint64_t{1} << (c % 64);
      }
    }
  }
}

const RelationViolations::Bits& RelationViolations::bitsOf(std::size_t a, std::size_t b) const {
  return broken_[pairIndex(a, b, object_count_)];
}

bool RelationViolations::breaks(std::size_t configuration, std::size_t a, std::size_t b) const {
  return (bitsOf(a, b)[configuration / 64] >> (configuration % 64)) & 1u;
}

std::size_t RelationViolations::predictedAccepted(const RelationTopology& topology) const {
  Bits caught((configuration_count_ + 63) / 64, 0);
  for (const auto& [a, b] : topology.relations()) {
    const Bits& bits = bitsOf(static_cast<std::size_t>(a), static_cast<std::size_t>(b));
    for (std::size_t w = 0; w < caught.size(); ++w)
      caught[w] |= bits[w];
  }
  std::size_t count = 0;
  for (std::uint64_t word : caught)
    count += std::bitset<64>(word).count();
  return configuration_count_ - count;
}

RelationTopology withCatchingRelations(const RelationTopology& start,
                                       const RelationViolations& violations, int max_height) {
  RelationTopology topology = start;
  std::vector<char> caught(violations.configurationCount(), 0);
  for (std::size_t c = 0; c < caught.size(); ++c) {
    for (const auto& [a, b] : topology.relations())
      caught[c] = caught[c] || violations.breaks(c, a, b);
  }
  while (true) {
    std::size_t best_gain = 0, best_a = 0, best_b = 0;
    for (std::size_t a = 0; a < topology.objectCount(); ++a) {
      for (std::size_t b = a + 1; b < topology.objectCount(); ++b) {
        if (topology.hasRelation(a, b))
          continue;
        std::size_t gain = 0;
        for (std::size_t c = 0; c < caught.size(); ++c)
          gain += !caught[c] && violations.breaks(c, a, b);
        if (gain <= best_gain)
          continue;
        RelationTopology grown = topology;
        grown.addRelation(a, b);
        if (max_height >= 1 && treeHeightOf(grown) > max_height)
          continue;
        best_gain = gain;
        best_a = a;
        best_b = b;
      }
    }
    if (best_gain == 0)
      return topology;
    topology.addRelation(best_a, best_b);
    for (std::size_t c = 0; c < caught.size(); ++c)
      caught[c] = caught[c] || violations.breaks(c, best_a, best_b);
  }
}

}  // namespace asr_ism_tree
