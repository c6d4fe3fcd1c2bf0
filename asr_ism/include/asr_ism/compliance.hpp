#pragma once

#include <cmath>

namespace asr_ism {

/// How well a vote agrees with a reference pose hypothesis, in [0, 1]: 1 for no deviation,
/// falling quadratically to 0 at the threshold and 0 beyond it. The quadratic shape tolerates
/// sensor noise well below the threshold and still separates larger deviations.

/// Position compliance for a distance d (given as d^2) and threshold t (given as t^2):
/// 1 - d^2 / t^2.
inline double positionCompliance(double distance_squared, double threshold_squared) {
  return distance_squared >= threshold_squared ? 0.0 : 1.0 - distance_squared / threshold_squared;
}

/// sin^2(theta / 2) from cos(theta / 2) = |q1 . q2|, the absolute dot product of unit quaternions.
inline double sinHalfSquared(double cos_half) {
  return std::max(0.0, 1.0 - cos_half * cos_half);
}

/// Orientation compliance for a rotation angle theta between vote and hypothesis and threshold
/// theta_max: 1 - sin^2(theta/2) / sin^2(theta_max/2). Like 1 - (theta/theta_max)^2 (within 0.5 %
/// of it at theta_max = 30 deg), but computed from the quaternion dot product without an arc
/// cosine, which dominated the run time of recognition.
inline double orientationCompliance(double cos_half, double sin_half_squared_of_threshold) {
  const double sin_half_squared = sinHalfSquared(cos_half);
  return sin_half_squared >= sin_half_squared_of_threshold
             ? 0.0
             : 1.0 - sin_half_squared / sin_half_squared_of_threshold;
}

}  // namespace asr_ism
