#pragma once

#include <cstddef>
#include <vector>

#include "asr_ism/ism_recognizer.hpp"

namespace asr_ism_tree {

/// Non-maximum suppression in pose: of `results` (best first), the best `count` such that none
/// lies within `radius` (metres) and `angle` (radians) of a better one kept. Near-duplicate
/// results (votes millimetres apart) then no longer fill a sub-ISM's few places, and a
/// hypothesis away from where a badly seen object pulls the best ones survives for the parent.
std::vector<asr_ism::IsmResult> poseDiverseResults(std::vector<asr_ism::IsmResult> results,
                                                   std::size_t count, double radius, double angle);

}  // namespace asr_ism_tree
