#include "asr_ism_tree/cli/topology_selection_options.hpp"

#include <string>

namespace asr_ism_tree::cli {

using asr_common::cli::UsageError;

TopologySelectionOptions topologySelectionOptionsFrom(const asr_common::cli::CommandLine& options,
                                                      double default_max_duration_ms) {
  TopologySelectionOptions selection;
  selection.test_count = static_cast<std::size_t>(
      options.integer("tests", static_cast<long long>(selection.test_count), 1, kMaxTestCount));
  selection.seed = static_cast<std::uint32_t>(options.integer("seed", selection.seed, 0, kMaxSeed));
  selection.alpha = options.number("alpha", selection.alpha);
  selection.beta = options.number("beta", selection.beta);
  if (!(selection.alpha >= 0 && selection.beta >= 0 && selection.alpha + selection.beta > 0))
    throw UsageError{"--alpha and --beta must be >= 0 and not both 0"};
  selection.max_duration_ms = options.number("max-duration-ms", default_max_duration_ms);
  if (!(selection.max_duration_ms >= 0))
    throw UsageError{"--max-duration-ms must be >= 0 (0: no budget)"};
  selection.max_evaluations = static_cast<std::size_t>(options.integer(
      "max-evaluations", static_cast<long long>(selection.max_evaluations), 2, kMaxEvaluations));
  selection.threads = static_cast<unsigned>(options.integer("threads", 0, 0, kMaxThreads));
  return selection;
}

}  // namespace asr_ism_tree::cli
