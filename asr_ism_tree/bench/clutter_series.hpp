#pragma once

// The clutter series of issue 12 (gedeck's recorded set 5 repeated with jitter), shared by the
// benchmarks, which time it, and the tests, which check its answers.

#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "asr_common/object.hpp"
#include "asr_ism/portable_random.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"
#include "asr_ism_tree/star_center.hpp"
#include "asr_ism_tree/tree_generation.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"

namespace asr_ism_tree::bench {

/// The recorded set the series repeats.
constexpr std::size_t kClutterRecordedSet = 5;

/// The demonstration the series is drawn from: gedeck of story_1 in the recordings folder.
inline asr_ism::Demonstration clutterDemonstration(const std::string& recordings) {
  return asr_ism::sqlite::readDemonstration(recordings + "/story_1.sqlite", "gedeck");
}

/// The trees the series is recognised with: gedeck's star and complete trees, by name.
inline std::vector<std::pair<std::string, IsmTree>> clutterTrees(
    const asr_ism::Demonstration& demonstration) {
  const auto& objects = demonstration.objects();
  std::vector<std::pair<std::string, IsmTree>> trees;
  trees.emplace_back(
      "star",
      generateIsmTree(demonstration,
                      RelationTopology::star(objects, chooseStarCenter(demonstration)), {}));
  trees.emplace_back("complete",
                     generateIsmTree(demonstration, RelationTopology::complete(objects), {}));
  return trees;
}

/// A configuration of `estimates` estimates: `recorded` itself (unless not `recorded_first`),
/// then copies of its estimates (keys kept) with Gaussian jitter of 2 cm per axis and 3 deg
/// about a random axis, seeded.
inline asr_common::Configuration clutteredCopies(const asr_common::Configuration& recorded,
                                                 std::size_t estimates, std::uint32_t seed,
                                                 bool recorded_first = true) {
  asr_ism::PortableRandom random(seed);
  asr_common::Configuration configuration;
  for (std::size_t i = 0; i < estimates; ++i) {
    asr_common::ObjectEstimate estimate = recorded[i % recorded.size()];
    if (i >= recorded.size() || !recorded_first) {
      const Eigen::Vector3d shift(random.gaussian(), random.gaussian(), random.gaussian());
      const Eigen::Vector3d axis(random.gaussian(), random.gaussian(), random.gaussian());
      estimate.pose.position += 0.02 * shift;
      estimate.pose.orientation = (estimate.pose.orientation *
                                   Eigen::Quaterniond(Eigen::AngleAxisd(
                                       3.0 * M_PI / 180.0 * random.gaussian(), axis.normalized())))
                                      .normalized();
    }
    configuration.push_back(estimate);
  }
  return configuration;
}

/// Recognition as it was before repeated detections were merged: every estimate enters the
/// search (the exhaustive search over every combination of repeats), with the exact search's
/// limits raised a hundredfold, so that where it completes in seconds its best is the
/// exhaustive one (TreeRecognitionStats::exact_searches_given_up says where it did not).
inline TreeRecognitionParameters exhaustiveClutterParameters(std::size_t max_estimates) {
  TreeRecognitionParameters parameters;
  parameters.max_estimates = max_estimates;
  parameters.merge_repeated_detections = false;
  parameters.exact_search_max_votes *= 100;
  parameters.exact_search_max_total_votes *= 100;
  parameters.exact_search_max_comparisons *= 100;
  parameters.exact_search_max_pose_steps *= 100;
  return parameters;
}

}  // namespace asr_ism_tree::bench
