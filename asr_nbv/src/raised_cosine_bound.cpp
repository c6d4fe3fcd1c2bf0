#include "asr_nbv/raised_cosine_bound.hpp"

#include <algorithm>
#include <cmath>

#include "asr_nbv/view_rating.hpp"

namespace asr_nbv {
namespace {

// Covers the rounding of the exact functions (acos, cos) near the table's points.
constexpr double kMargin = 1e-7;

}  // namespace

RaisedCosineBound::RaisedCosineBound(double threshold)
    : distance_scale_(kEntries / threshold),
      cosine_scale_(kEntries / (1.0 - std::cos(std::min(threshold, M_PI)))),
      by_distance_(kEntries + 1),
      by_cosine_(kEntries + 1) {
  for (int i = 0; i <= kEntries; ++i) {
    by_distance_[i] = raisedCosine(i / distance_scale_, threshold) + kMargin;
    const double cosine = std::clamp(1.0 - i / cosine_scale_, -1.0, 1.0);
    by_cosine_[i] = raisedCosine(std::acos(cosine), threshold) + kMargin;
  }
}

}  // namespace asr_nbv
