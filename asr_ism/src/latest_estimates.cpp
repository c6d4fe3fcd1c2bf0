#include "asr_ism/latest_estimates.hpp"

namespace asr_ism {

void LatestEstimates::update(const ObjectEstimate& estimate, double time) {
  const auto found = latest_.find(estimate.key);
  if (found == latest_.end()) {
    latest_.emplace(estimate.key, Entry{estimate, time});
  } else if (time >= found->second.time) {
    // Equal times: the later call wins, as a detector's repeated report of one frame should.
    found->second = Entry{estimate, time};
  }
}

Configuration LatestEstimates::current(double now, double timeout) const {
  Configuration configuration;
  for (const auto& [key, entry] : latest_) {
    if (timeout <= 0.0 || now - entry.time <= timeout)
      configuration.push_back(entry.estimate);
  }
  return configuration;
}

}  // namespace asr_ism
