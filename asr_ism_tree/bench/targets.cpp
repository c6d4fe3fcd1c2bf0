#include "targets.hpp"

#include <cmath>
#include <cstdio>
#include <ostream>

namespace asr_ism_tree::bench {
namespace {

constexpr double kStarMedianMs = 0.5;
constexpr double kCompleteMedianMs = 3.0;
constexpr double kGedeckEndeCompleteMedianMs = 70.0;
constexpr double kSyntheticMedianMs = 50.0;
constexpr double kLearnMs = 100.0;
constexpr double kMissingOneTolerance = 0.02;

std::string milliseconds(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.3f ms", value);
  return buffer;
}

// The row that is worst by `badness` among rows passing `filter`, or nullptr.
template <typename Row, typename Filter, typename Badness>
const Row* worst(const std::vector<Row>& rows, Filter filter, Badness badness) {
  const Row* found = nullptr;
  for (const Row& row : rows) {
    if (filter(row) && (found == nullptr || badness(row) > badness(*found)))
      found = &row;
  }
  return found;
}

std::string number(double value, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*f", decimals, value);
  return buffer;
}

std::string where(const SceneRow& row) {
  return " (" + row.scene + ", " + row.topology + ")";
}

// Clutter (issue 12): 1,000 estimates of the scene's types within 100 ms, 10,000 within 1 s.
void checkClutterTimes(const std::vector<ClutterRow>& clutter, const std::string& series,
                       std::vector<asr_common::cli::Target>& checks) {
  for (const ClutterRow& row : clutter) {
    const double limit = row.estimates == 1000 ? 100.0 : row.estimates == 10000 ? 1000.0 : 0.0;
    if (limit == 0.0)
      continue;
    checks.push_back({series + " " + row.topology + " " + std::to_string(row.estimates) +
                          " estimates <= " + milliseconds(limit),
                      row.run ? milliseconds(row.milliseconds) : "not run (too slow)",
                      row.run && row.milliseconds <= limit});
  }
}

void checkClutter(const std::vector<ClutterRow>& clutter,
                  std::vector<asr_common::cli::Target>& checks) {
  checkClutterTimes(clutter, "clutter", checks);
  // ... with the results of before the merge where those finish: the exhaustive best.
  for (const std::string topology : {"star", "complete"}) {
    std::size_t compared = 0, same = 0;
    std::string differing;
    for (const ClutterRow& row : clutter) {
      if (row.topology != topology || row.exhaustive_best_confidence < 0.0)
        continue;
      ++compared;
      const std::string outcome = comparedWithExhaustive(row);
      if (outcome == "same")
        ++same;
      else
        differing += ", " + std::to_string(row.estimates) + ": " + outcome;
    }
    if (compared == 0)
      continue;
    checks.push_back({"clutter " + topology + " best = exhaustive best up to " +
                          std::to_string(exhaustiveUpTo(topology)) + " estimates",
                      "same in " + std::to_string(same) + " of " + std::to_string(compared) +
                          " rows" + differing,
                      same == compared});
  }
}

}  // namespace

std::vector<asr_common::cli::Target> checkTargets(const std::vector<SceneRow>& scenes,
                                                  const std::vector<SyntheticRow>& synthetic,
                                                  const std::vector<ClutterRow>& clutter,
                                                  const std::vector<ClutterRow>& jittered_clutter) {
  std::vector<asr_common::cli::Target> checks;
  checkClutter(clutter, checks);
  checkClutterTimes(jittered_clutter, "clutter without its recorded set", checks);
  for (const SceneRow& row : scenes) {
    if (row.topology != "complete")
      continue;
    const double limit =
        row.scene == "Gedeck_Ende" ? kGedeckEndeCompleteMedianMs : kCompleteMedianMs;
    checks.push_back({"complete " + row.scene + " median <= " + milliseconds(limit),
                      milliseconds(row.recog_median_ms), row.recog_median_ms <= limit});
  }
  const auto is_star = [](const SceneRow& row) { return row.topology == "star"; };
  const auto any = [](const auto&) { return true; };
  if (const SceneRow* row =
          worst(scenes, is_star, [](const SceneRow& r) { return r.recog_median_ms; })) {
    checks.push_back({"star median <= " + milliseconds(kStarMedianMs) + " for every scene",
                      "worst " + milliseconds(row->recog_median_ms) + where(*row),
                      row->recog_median_ms <= kStarMedianMs});
  }
  if (const SceneRow* row = worst(scenes, any, [](const SceneRow& r) { return r.learn_ms; })) {
    checks.push_back({"learning incl. storage <= " + milliseconds(kLearnMs) + " per scene",
                      "worst " + milliseconds(row->learn_ms) + where(*row),
                      row->learn_ms <= kLearnMs});
  }
  if (const SceneRow* row =
          worst(scenes, any, [](const SceneRow& r) { return -r.recognised_fraction; })) {
    checks.push_back({"recognised_fraction 1.0 for every scene and topology",
                      "lowest " + number(row->recognised_fraction, 3) + where(*row),
                      row->recognised_fraction >= 1.0});
  }
  const auto star_deviation = [](const SceneRow& r) {
    const double n = static_cast<double>(r.objects);
    return std::abs(r.missing_one_confidence - (n - 1.0) / n);
  };
  if (const SceneRow* row = worst(scenes, is_star, star_deviation)) {
    checks.push_back({"star missing_one_confidence within 0.02 of (N-1)/N",
                      "worst deviation " + number(star_deviation(*row), 4) + where(*row),
                      star_deviation(*row) <= kMissingOneTolerance});
  }
  for (const auto& [objects, steps] : {std::pair<std::size_t, std::size_t>{10, 400}, {6, 1000}}) {
    for (const SyntheticRow& row : synthetic) {
      if (row.objects == objects && row.steps == steps) {
        checks.push_back(
            {"synthetic complete " + std::to_string(objects) + " objects x " +
                 std::to_string(steps) + " steps median <= " + milliseconds(kSyntheticMedianMs),
             milliseconds(row.recog_median_ms), row.recog_median_ms <= kSyntheticMedianMs});
      }
    }
  }
  if (!synthetic.empty()) {
    const SyntheticRow* row =
        worst(synthetic, any, [](const SyntheticRow& r) { return -r.recognised_fraction; });
    checks.push_back({"synthetic recognised_fraction 1.0 for every size",
                      "lowest " + number(row->recognised_fraction, 3) + " (" +
                          std::to_string(row->objects) + " x " + std::to_string(row->steps) + ")",
                      row->recognised_fraction >= 1.0});
  }
  return checks;
}

}  // namespace asr_ism_tree::bench
