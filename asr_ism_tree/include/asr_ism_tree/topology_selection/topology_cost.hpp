#pragma once

#include "asr_ism_tree/topology_selection/topology_evaluation.hpp"

namespace asr_ism_tree {

/// The cost the search minimises: alpha * normalised errors + beta * normalised work, where errors
/// = the share of all test configurations that the tree judges otherwise than their labels:
/// invalid ones accepted (numFPs x the invalid share) and valid ones rejected (x the valid share).
/// Each configuration counts once, so the few valid configurations of a scene weigh no more than
/// the many invalid ones, yet a tree that rejects everything still costs as many errors as there
/// are valid configurations; without that term the search drifts to sparse chains that reject
/// almost everything. Each term is normalised to [0, 1] between the best and worst of the star and
/// complete topologies (the
/// extremes of the search space: the star is fastest and the least strict, the complete topology
/// slowest and, by construction of the labels, without false positives). Values outside the
/// range are not clamped, so a topology worse than both extremes costs more than 1 per term.
/// A topology over the work budget (TopologyMeasures::over_budget, or mean work above
/// `max_mean_work` if that is > 0) costs kOverBudget + its work / the budget: more than any
/// topology within the budget, and the less work the better, so a search that starts over the
/// budget is led towards it.
class TopologyCost {
 public:
  static constexpr double kOverBudget = 1000.0;

  /// `valid_share`: the share of valid configurations among the test configurations, in [0, 1].
  TopologyCost(const TopologyMeasures& star, const TopologyMeasures& complete, double alpha,
               double beta, double max_mean_work = 0.0, double valid_share = 0.5);

  double operator()(const TopologyMeasures& measures) const;

  /// (value - low) / (high - low); 0 when high == low (the term cannot tell topologies apart).
  static double normalised(double value, double low, double high);

  /// The share of test configurations misjudged: numFPs x (1 - valid share) + share of valid
  /// configurations rejected x valid share.
  double errors(const TopologyMeasures& measures) const;

 private:
  double valid_share_;
  double alpha_;
  double beta_;
  double error_low_, error_high_;
  double work_low_, work_high_;
  double max_mean_work_;
};

}  // namespace asr_ism_tree
