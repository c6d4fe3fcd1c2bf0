#pragma once

#include <cstdint>
#include <string>

#include "asr_ism/demonstration.hpp"

namespace asr_ism {

/// Synthetic demonstrations for benchmarks, tests and demos. Everything here is deterministic for
/// a seed and the same on every platform: random numbers come from std::mt19937 (whose output the
/// C++ standard fixes) through distributions implemented here, not the standard library's.
/// Objects stand upright on a table whose top is at z = 0.75 m in the `map` frame.

/// `objects` objects (types "object_0", "object_1", ..., id "0") placed on a 1 m x 1 m table area
/// and demonstrated over `steps` time steps, like a person moving them around: each object slides
/// smoothly by a few centimetres up to about 30 cm and turns about the vertical by a few up to
/// about 30 degrees over the demonstration, so the relative arrangement drifts; each step adds
/// sensor noise (3 mm per axis, about 1 degree). The motion depends on the seed, not on `steps`:
/// more steps sample the same motion more densely. Every object is observed in every step.
/// Throws InputError for zero objects or steps.
Demonstration makeSyntheticDemonstration(std::size_t objects, std::size_t steps, std::uint32_t seed,
                                         const std::string& scene = "synthetic");

/// The suite's own small demonstration, scene "breakfast": a place setting (PlateDeep, Cup,
/// Fork, Knife, Spoon, CerealBox, each with id "0") recorded over 60 time steps while a person
/// slides the whole setting about 40 cm along the table, turning it slightly, and nudges the
/// cup and the cutlery by a few centimetres and degrees, with sensor noise as above.
/// Setting frame: x to the right of the person sitting at it, y away from them, z up.
Demonstration makeBreakfastDemonstration(std::uint32_t seed);

/// A copy of `configuration` with every pose moved rigidly by `motion` (pose -> motion * pose,
/// in the map frame); relative poses, and hence recognition results, stay the same.
Configuration transformConfiguration(const Configuration& configuration, const Pose& motion);

/// A copy of `configuration` in which the object `key` is shifted by `offset` (map frame) and
/// turned by `rotation` about its own origin (rotation given in the map frame). Throws InputError
/// if the configuration does not contain `key`.
Configuration disturbConfiguration(
    const Configuration& configuration, const ObjectKey& key, const Eigen::Vector3d& offset,
    const Eigen::Quaterniond& rotation = Eigen::Quaterniond::Identity());

/// A copy of `configuration` with fresh, independent sensor noise on every pose: Gaussian-like
/// position noise of `position_sigma` metres per axis, and a rotation whose angle has an RMS of
/// `angle_sigma` radians about a random axis. Deterministic for a seed.
Configuration addSensorNoise(const Configuration& configuration, double position_sigma,
                             double angle_sigma, std::uint32_t seed);

}  // namespace asr_ism
