#pragma once

#include <string>

#include "asr_ism/ism_recognizer.hpp"

#include "asr_common/input_limits.hpp"

// Checks of recognition parameters and models against the suite's input limits.
namespace asr_ism {

using asr_common::kMaxBinSize;
using asr_common::kMaxCoordinate;
using asr_common::kMaxRelationLength;
using asr_common::kMinBinSize;

/// Throws InputError naming `what` unless bin_size is in [kMinBinSize, kMaxBinSize] and
/// max_angle_deviation in (0, pi].
void checkRecognitionParameters(const IsmRecognitionParameters& parameters,
                                const std::string& what);

/// How far apart votes of one ISM can land when a tree of `height` levels whose longest relation
/// is `longest_relation` metres recognises estimates within kMaxCoordinate. Throws InputError
/// naming `what` if that is beyond what a voting space with `bin_size` bins can hold.
void checkVotingExtent(double bin_size, int height, double longest_relation,
                       const std::string& what);

}  // namespace asr_ism
