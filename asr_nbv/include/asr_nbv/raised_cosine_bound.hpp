#pragma once

#include <vector>

namespace asr_nbv {

/// Upper bounds of raisedCosine(d, threshold) by table look-up, with no arc or cosine function:
/// for the planner's first pass, whose utilities only bound the exact ones (the exact rating
/// decides). Never below the exact value, and above it by at most about 1 / kEntries.
class RaisedCosineBound {
 public:
  static constexpr int kEntries = 2048;

  explicit RaisedCosineBound(double threshold);

  /// >= raisedCosine(d, threshold), for d >= 0.
  double ofDistance(double d) const {
    const double index = d * distance_scale_;
    return index < kEntries + 1.0 ? by_distance_[static_cast<int>(index)] : 0.0;
  }

  /// >= raisedCosine of the angle whose cosine is `cosine` (in [-1, 1]).
  double ofCosine(double cosine) const {
    const double index = (1.0 - cosine) * cosine_scale_;
    if (!(index < kEntries + 1.0))
      return 0.0;
    return by_cosine_[index > 0.0 ? static_cast<int>(index) : 0];
  }

 private:
  double distance_scale_, cosine_scale_;
  // Entry i: the largest value on [i, i + 1) of the table's variable (the function falls), plus
  // a margin for rounding; entry kEntries covers the threshold itself.
  std::vector<double> by_distance_, by_cosine_;
};

}  // namespace asr_nbv
