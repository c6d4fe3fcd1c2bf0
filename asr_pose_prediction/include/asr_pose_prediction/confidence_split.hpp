#pragma once

#include <cstddef>
#include <vector>

namespace asr_pose_prediction {

/// Splits `total` poses among instances in proportion to their confidences, exactly and
/// deterministically (largest remainders): each instance first gets the whole part of its quota
/// total * c_i / sum(c); the poses left over go one each to the instances with the largest
/// fractional parts, and among equal fractions (compared to 1e-9) to the earlier (better) instance.
/// The counts always add up to `total`. If every confidence is 0, the split is even.
/// Throws InputError for a negative or non-finite confidence.
std::vector<std::size_t> splitByConfidence(std::size_t total,
                                           const std::vector<double>& confidences);

}  // namespace asr_pose_prediction
