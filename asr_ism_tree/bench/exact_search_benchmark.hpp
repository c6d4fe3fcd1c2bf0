#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "asr_ism_tree/tree_recognizer.hpp"

namespace asr_ism_tree::bench {

/// What the exact search costs where its bound is loosest: the test configurations topology
/// selection draws (objects placed by relations demonstrated at other times, most of them far
/// from every demonstrated configuration), recognised by a scene's complete tree with and
/// without the exact search.
struct ExactSearchRow {
  std::string scene;
  std::size_t configurations = 0;
  double first_mean_ms = 0.0;  // the first evaluation alone (exact_best = false)
  double first_max_ms = 0.0;
  double exact_mean_ms = 0.0;  // with the exact search (the default)
  double exact_max_ms = 0.0;
  std::size_t exact_max_comparisons = 0;  // of the exact search in one recognition
  std::size_t given_up = 0;               // configurations where the exact search gave up
  std::size_t improved = 0;               // configurations whose best confidence it raised
  std::size_t subset_searches =
      0;                        // recognitions of subsets of the seen objects, all configurations
  std::size_t subsets_cut = 0;  // configurations where those ran out of comparisons
  double largest_gain = 0.0;    // in confidence
};

/// `scene`: the kitchen scene to measure (empty: all ten); `tests` configurations each.
std::vector<ExactSearchRow> benchmarkExactSearch(const std::string& recordings,
                                                 const std::string& scene, std::size_t tests,
                                                 const TreeRecognitionParameters& parameters,
                                                 std::ostream& progress);

void printExactSearchTable(std::ostream& out, const std::vector<ExactSearchRow>& rows);

/// `asr_bench exact [--recordings DIR] [--scene NAME] [--tests N] [--max-votes N]
/// [--max-comparisons N] [--diverse N] [--subsets N]`.
int runExactSearchCommand(const std::vector<std::string>& arguments);

}  // namespace asr_ism_tree::bench
