#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "clutter_benchmark.hpp"
#include "recognition_benchmark.hpp"
#include "synthetic_benchmark.hpp"

namespace asr_ism_tree::bench {

/// One performance or quality target of the suite and how the measurement compares with it.
struct TargetCheck {
  std::string target;
  std::string measured;
  bool met = false;
};

/// The suite's targets for the rows at hand; targets whose rows were not measured (scenes
/// skipped, --no-synthetic) are left out.
std::vector<TargetCheck> checkTargets(const std::vector<SceneRow>& scenes,
                                      const std::vector<SyntheticRow>& synthetic,
                                      const std::vector<ClutterRow>& clutter = {});

void printTargets(std::ostream& out, const std::vector<TargetCheck>& checks);

}  // namespace asr_ism_tree::bench
