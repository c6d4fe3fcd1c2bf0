#include "prediction_targets.hpp"

#include <cmath>
#include <cstdio>
#include <ostream>

namespace asr_pose_prediction::bench {
namespace {

constexpr double kRuntimeLimitMs = 1.0;  // 100 poses x every object, 10 objects x 400 steps
constexpr double kDistanceLimitM = 0.05;
constexpr double kAngleLimitDeg = 15.0;

std::string withUnit(double number, const char* pattern) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), pattern, number);
  return buffer;
}

}  // namespace

std::vector<asr_common::cli::Target> checkPredictionTargets(
    const std::vector<RuntimeRow>& synthetic, const std::vector<AccuracyRow>& combined) {
  std::vector<asr_common::cli::Target> targets;
  for (const RuntimeRow& row : synthetic) {
    if (row.objects != 10 || row.steps != 400)
      continue;
    targets.push_back(
        {"synthetic 10 objects x 400 steps, " + row.topology + ": " + std::to_string(row.samples) +
             " poses of every object <= " + withUnit(kRuntimeLimitMs, "%.1f ms") + " (median)",
         withUnit(row.median_ms, "%.4f ms"), row.median_ms <= kRuntimeLimitMs});
  }
  for (const AccuracyRow& row : combined) {
    if (row.cases == 0)
      continue;
    const std::string where = " over all scenes and left-out objects, " + row.topology +
                              (row.held_out ? ", held-out sets" : "") + " (" +
                              std::to_string(row.cases) + " cases)";
    const double distance = distributionOf(row.distances_m).median;
    targets.push_back({"median distance to the nearest predicted pose <= " +
                           withUnit(kDistanceLimitM * 100.0, "%.0f cm") + where,
                       withUnit(distance * 100.0, "%.2f cm"), distance <= kDistanceLimitM});
    const double angle = distributionOf(row.smallest_angles_deg).median;
    targets.push_back({"median angle to the nearest predicted orientation <= " +
                           withUnit(kAngleLimitDeg, "%.0f deg") + where,
                       withUnit(angle, "%.2f deg"), angle <= kAngleLimitDeg});
    const double angle_at_nearest = distributionOf(row.angles_at_nearest_deg).median;
    targets.push_back({"median angle of the pose nearest in position <= " +
                           withUnit(kAngleLimitDeg, "%.0f deg") + where,
                       withUnit(angle_at_nearest, "%.2f deg"), angle_at_nearest <= kAngleLimitDeg});
  }
  return targets;
}

nlohmann::ordered_json targetsToJson(const std::vector<asr_common::cli::Target>& targets) {
  nlohmann::ordered_json array = nlohmann::ordered_json::array();
  for (const asr_common::cli::Target& target : targets)
    array.push_back(
        {{"target", target.target}, {"measured", target.measured}, {"met", target.met}});
  return array;
}

}  // namespace asr_pose_prediction::bench
