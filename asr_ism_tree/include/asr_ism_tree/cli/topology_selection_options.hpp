#pragma once

#include "asr_common/cli/command_line.hpp"
#include "asr_ism_tree/topology_selection/topology_selection.hpp"

namespace asr_ism_tree::cli {

/// The search options every command that selects topologies takes: --tests N, --seed S,
/// --alpha A, --beta B, --max-duration-ms D (default `default_max_duration_ms`; 0: no budget),
/// --max-evaluations E, --threads T (0: one per core). Unset options keep
/// TopologySelectionOptions' defaults. Throws UsageError naming an option out of range.
TopologySelectionOptions topologySelectionOptionsFrom(const asr_common::cli::CommandLine& options,
                                                      double default_max_duration_ms);

}  // namespace asr_ism_tree::cli
