#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "asr_common/object.hpp"
#include "benchmark_settings.hpp"
#include "clutter_series.hpp"

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
  // The best instance's SceneInstance::search_complete: false where a search ran out of its
  // work limits, so the best found before it stands (a lower bound of the exhaustive best).
  bool search_complete = false;
  bool run = false;  // false: skipped, a smaller size of this topology took too long
  // The best confidence of the exhaustive search (every repeated detection enters: recognition
  // as it was before they were merged, seconds of work; exhaustiveClutterParameters()), and its
  // time; measured up to exhaustiveUpTo() estimates, negative where not measured.
  double exhaustive_best_confidence = -1.0;
  double exhaustive_milliseconds = -1.0;
  bool exhaustive_given_up = false;  // its exact search ran out of its (raised) limits
};

/// Up to how many estimates the series compares with the exhaustive search: star 500 (6.4 s on
/// the quiet 2-core machine; 1,000 took 32 s), complete 2,000 (6 s; 1,000 took 2 s).
std::size_t exhaustiveUpTo(const std::string& topology);

/// Estimate counts of the clutter series.
std::vector<std::size_t> clutterSizes();

/// The clutter series for gedeck's star and complete trees. A topology's series stops once one
/// size took longer than 30 s.
std::vector<ClutterRow> benchmarkClutter(const std::string& recordings,
                                         const BenchmarkSettings& settings, std::ostream& progress);

/// "same" where the row's best equals the exhaustive best (within 1e-9), else "lower by X" (or
/// "higher by X"), with a note where the exhaustive search gave up; empty where not measured.
std::string comparedWithExhaustive(const ClutterRow& row);

/// The series as a table.
void printClutterTable(std::ostream& out, const std::vector<ClutterRow>& rows);

/// The series without its recorded set (every copy jittered, sizes as above): no repeat fits
/// exactly, so the searches may give up (`search_complete` false), and the exhaustive best is
/// not known (not measured).
std::vector<ClutterRow> benchmarkJitteredClutter(const std::string& recordings,
                                                 const BenchmarkSettings& settings,
                                                 std::ostream& progress);

/// That series as a table.
void printJitteredClutterTable(std::ostream& out, const std::vector<ClutterRow>& rows);

}  // namespace asr_ism_tree::bench
