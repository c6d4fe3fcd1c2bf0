#pragma once

#include <algorithm>
#include <chrono>
#include <vector>

namespace asr_common::cli {

/// Wall-clock milliseconds a call takes, on the monotonic clock (immune to clock adjustments).
template <typename Call>
double millisecondsOf(Call&& call) {
  const auto start = std::chrono::steady_clock::now();
  call();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

/// Median of the values (mean of the middle two for an even count); 0 for none.
inline double median(std::vector<double> values) {
  if (values.empty())
    return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t middle = values.size() / 2;
  return values.size() % 2 == 1 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

inline double maximum(const std::vector<double>& values) {
  return values.empty() ? 0.0 : *std::max_element(values.begin(), values.end());
}

/// Indices of `count` steps spread evenly over [0, total), first and last included; all of them
/// if there are no more than `count`.
inline std::vector<std::size_t> evenlySpaced(std::size_t total, std::size_t count) {
  std::vector<std::size_t> indices;
  if (total <= count) {
    for (std::size_t i = 0; i < total; ++i)
      indices.push_back(i);
  } else if (count == 1) {
    indices.push_back(0);
  } else {
    for (std::size_t i = 0; i < count; ++i)
      indices.push_back(i * (total - 1) / (count - 1));
  }
  return indices;
}

}  // namespace asr_common::cli
