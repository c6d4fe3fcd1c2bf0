#include "asr_ism_tree/cli/topology_selection_options.hpp"

#include <string>

namespace asr_ism_tree::cli {

using asr_common::cli::UsageError;

TopologySelectionOptions topologySelectionOptionsFrom(const asr_common::cli::CommandLine& options,
                                                      double default_max_duration_ms) {
  TopologySelectionOptions selection;
  const long long tests = options.integer("tests", static_cast<long long>(selection.test_count));
  if (tests < 1)
    throw UsageError{"--tests must be at least 1 (got " + std::to_string(tests) + ")"};
  selection.test_count = static_cast<std::size_t>(tests);
  selection.seed = static_cast<std::uint32_t>(options.integer("seed", selection.seed));
  selection.alpha = options.number("alpha", selection.alpha);
  selection.beta = options.number("beta", selection.beta);
  if (!(selection.alpha >= 0 && selection.beta >= 0 && selection.alpha + selection.beta > 0))
    throw UsageError{"--alpha and --beta must be >= 0 and not both 0"};
  selection.max_duration_ms = options.number("max-duration-ms", default_max_duration_ms);
  if (!(selection.max_duration_ms >= 0))
    throw UsageError{"--max-duration-ms must be >= 0 (0: no budget)"};
  const long long evaluations =
      options.integer("max-evaluations", static_cast<long long>(selection.max_evaluations));
  if (evaluations < 2)
    throw UsageError{"--max-evaluations must be at least 2"};
  selection.max_evaluations = static_cast<std::size_t>(evaluations);
  selection.threads = static_cast<unsigned>(options.integer("threads", 0));
  return selection;
}

}  // namespace asr_ism_tree::cli
