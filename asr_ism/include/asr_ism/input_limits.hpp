#pragma once

#include <string>

#include "asr_ism/ism_recognizer.hpp"

// The ranges the suite accepts for the numbers users supply (estimates, demonstrations, models,
// parameters). Each is far beyond any indoor scene, and together they guarantee that a vote of an
// accepted model on accepted estimates always fits the voting space: nothing accepted at intake
// can fail later inside a recogniser.
namespace asr_ism {

/// Largest accepted |x|, |y| or |z| of an object pose, in metres from the fixed frame's origin.
constexpr double kMaxCoordinate = 1000.0;
/// Longest accepted relation (distance between two objects of one scene seen together), metres.
constexpr double kMaxRelationLength = 100.0;
/// Accepted bin sizes (the position tolerance of recognition), metres.
constexpr double kMinBinSize = 0.01;
constexpr double kMaxBinSize = 10.0;

/// Throws InputError naming `what` unless bin_size is in [kMinBinSize, kMaxBinSize] and
/// max_angle_deviation in (0, pi].
void checkRecognitionParameters(const IsmRecognitionParameters& parameters,
                                const std::string& what);

/// How far from the origin votes can land when a tree of `height` levels whose longest relation
/// is `longest_relation` metres recognises estimates within kMaxCoordinate. Throws InputError
/// naming `what` if that is beyond what a voting space with `bin_size` bins can hold.
void checkVotingExtent(double bin_size, int height, double longest_relation,
                       const std::string& what);

}  // namespace asr_ism
