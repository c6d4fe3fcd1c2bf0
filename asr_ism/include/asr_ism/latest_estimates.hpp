#pragma once

#include <map>

#include "asr_ism/common_types.hpp"

namespace asr_ism {

/// The newest estimate of every object seen, for nodes that act on "what is there now": an
/// object not seen for longer than a time-out is left out, since it may have been moved away.
/// Times are seconds on any monotonic clock the caller uses consistently.
class LatestEstimates {
 public:
  /// Keeps `estimate` as its object's newest unless a newer one is already there.
  void update(const ObjectEstimate& estimate, double time);

  /// The newest estimate of every object seen within `timeout` seconds before `now`, ordered by
  /// object key; all of them if `timeout` <= 0.
  Configuration current(double now, double timeout) const;

  std::size_t size() const { return latest_.size(); }
  void clear() { latest_.clear(); }

 private:
  struct Entry {
    ObjectEstimate estimate;
    double time = 0.0;
  };
  std::map<ObjectKey, Entry> latest_;
};

}  // namespace asr_ism
