#pragma once

#include "asr_common/object.hpp"
#include "asr_ism_tree/ism_tree.hpp"

namespace asr_ism_tree {

/// The estimates (in configuration order) the scene of `tree` can match: those of its objects'
/// types. A scene's answer depends on these alone, so where they stay the same its last answer
/// is still the answer.
asr_common::Configuration matchableEstimates(const IsmTree& tree,
                                             const asr_common::Configuration& configuration);

/// Equal bit for bit: an estimate that moved by rounding only may change the answer as well.
bool sameEstimates(const asr_common::Configuration& a, const asr_common::Configuration& b);

}  // namespace asr_ism_tree
