#include "asr_ism_tree/topology_selection/topology_cost.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "asr_common/input_error.hpp"

namespace asr_ism_tree {

TopologyCost::TopologyCost(const TopologyMeasures& star, const TopologyMeasures& complete,
                           double alpha, double beta, double max_mean_work, double valid_share)
    : valid_share_(valid_share),
      alpha_(alpha),
      beta_(beta),
      error_low_(std::min(errors(star), errors(complete))),
      error_high_(std::max(errors(star), errors(complete))),
      work_low_(std::min(star.mean_work, complete.mean_work)),
      work_high_(std::max(star.mean_work, complete.mean_work)),
      max_mean_work_(max_mean_work) {
  if (!std::isfinite(alpha) || !std::isfinite(beta) || alpha < 0 || beta < 0 || alpha + beta <= 0) {
    throw asr_common::InputError(
        "the cost weights alpha and beta must be >= 0, finite and not both 0");
  }
  if (!(valid_share >= 0.0 && valid_share <= 1.0))
    throw asr_common::InputError("the share of valid test configurations must be in [0, 1] (got " +
                                 std::to_string(valid_share) + ")");
}

double TopologyCost::normalised(double value, double low, double high) {
  return high > low ? (value - low) / (high - low) : 0.0;
}

double TopologyCost::errors(const TopologyMeasures& measures) const {
  return (1.0 - valid_share_) * measures.false_positive_rate +
         valid_share_ * (1.0 - measures.true_positive_rate);
}

double TopologyCost::operator()(const TopologyMeasures& measures) const {
  if (max_mean_work_ > 0.0 && (measures.over_budget || measures.mean_work > max_mean_work_))
    return kOverBudget + measures.mean_work / max_mean_work_;
  return alpha_ * normalised(errors(measures), error_low_, error_high_) +
         beta_ * normalised(measures.mean_work, work_low_, work_high_);
}

}  // namespace asr_ism_tree
