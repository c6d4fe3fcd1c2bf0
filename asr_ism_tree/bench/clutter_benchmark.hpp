#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "asr_common/object.hpp"
#include "benchmark_settings.hpp"

namespace asr_ism_tree::bench {

/// Recognition of one cluttered configuration: every object of recorded set 5 of gedeck repeated
/// with jitter (2 cm, 3 deg, seeded) up to `estimates` estimates, all of the scene's types.
struct ClutterRow {
  std::string topology;  // "star" or "complete"
  std::size_t estimates = 0;
  double milliseconds = 0.0;  // fastest of up to three runs; 0 if not run
  double best_confidence = 0.0;
  std::size_t instances = 0;
  std::size_t merged = 0;  // repeated detections merged away
  // The search over every repeat ran out of its work limits: the merged best stands.
  bool repeat_search_given_up = false;
  bool run = false;  // false: skipped, a smaller size of this topology took too long
  // The best confidence of the exhaustive search (every repeated detection enters, seconds of
  // work); measured for the smallest size only, negative where not measured.
  double exhaustive_best_confidence = -1.0;
};

/// Estimate counts of the clutter series.
std::vector<std::size_t> clutterSizes();

/// The clutter series for gedeck's star and complete trees. A topology's series stops once one
/// size took longer than 30 s.
std::vector<ClutterRow> benchmarkClutter(const std::string& recordings,
                                         const BenchmarkSettings& settings, std::ostream& progress);

/// The series as a table.
void printClutterTable(std::ostream& out, const std::vector<ClutterRow>& rows);

/// A configuration of `estimates` jittered copies of `recorded`'s estimates, keys kept.
asr_common::Configuration clutteredCopies(const asr_common::Configuration& recorded,
                                          std::size_t estimates, std::uint32_t seed);

}  // namespace asr_ism_tree::bench
