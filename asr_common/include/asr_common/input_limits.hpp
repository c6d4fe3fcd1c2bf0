#pragma once

// The ranges the suite accepts for the numbers users supply (estimates, demonstrations, models,
// parameters). Each is far beyond any indoor scene, and together they guarantee that a vote of an
// accepted model on accepted estimates always fits the voting space: nothing accepted at intake
// can fail later inside a recogniser. asr_ism/input_limits.hpp checks recognition parameters and
// models against them.
namespace asr_common {

/// Largest accepted |x|, |y| or |z| of an object pose, in metres from the fixed frame's origin.
constexpr double kMaxCoordinate = 1000.0;
/// Longest accepted relation (distance between two objects of one scene seen together), metres.
constexpr double kMaxRelationLength = 100.0;
/// Accepted bin sizes (the position tolerance of recognition), metres.
constexpr double kMinBinSize = 0.01;
constexpr double kMaxBinSize = 10.0;

}  // namespace asr_common
