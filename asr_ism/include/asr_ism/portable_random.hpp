#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <random>

namespace asr_ism {

/// Uniform in [0, 1) with 53 random bits from two raw draws of `engine` (in a fixed order).
double uniformUnit(std::mt19937& engine);

/// An integer uniform in [0, bound) from raw 32-bit draws (multiply-and-shift with rejection,
/// so every value is exactly equally likely). bound must be > 0.
std::uint32_t uniformBelow(std::mt19937& engine, std::uint32_t bound);

// Random numbers that are the same on every platform: std::mt19937's raw output is fixed by the
// standard, but std::uniform_real_distribution and std::normal_distribution are not, so the
// distributions are implemented here from the raw 32-bit draws with plain arithmetic. Draws are
// made in separate statements, never as two arguments of one call or operands of one operator,
// whose evaluation order C++ leaves open (GCC and Clang differ).
class PortableRandom {
 public:
  explicit PortableRandom(std::uint32_t seed) : engine_(seed) {}
  explicit PortableRandom(std::mt19937 engine) : engine_(engine) {}

  /// Uniform in [0, 1), with 53 random bits (two draws, in a fixed order).
  double uniform() { return uniformUnit(engine_); }

  /// An integer uniform in [0, bound); bound must be > 0.
  std::uint32_t below(std::uint32_t bound) { return uniformBelow(engine_, bound); }

  double uniform(double low, double high) { return low + (high - low) * uniform(); }

  /// Mean 0, variance 1, close to a normal distribution: the Irwin-Hall sum of 12 uniforms minus 6.
  /// Unlike Box-Muller it needs no logarithm, so it is bit-identical everywhere; it is bounded by
  /// +-6, which sensor noise never needs to exceed.
  double gaussian() {
    double sum = 0.0;
    for (int i = 0; i < 12; ++i)
      sum += uniform();
    return sum - 6.0;
  }

  /// -1 or +1 with equal probability.
  double sign() { return uniform() < 0.5 ? -1.0 : 1.0; }

  /// A magnitude uniform in [low, high) with a random sign (sign drawn first).
  double signedUniform(double low, double high) {
    const double sign_of_value = sign();
    return sign_of_value * uniform(low, high);
  }

  /// A point uniform in the square [low, high)^2 (x drawn first).
  Eigen::Vector2d uniformSquare(double low, double high) {
    const double x = uniform(low, high);
    const double y = uniform(low, high);
    return Eigen::Vector2d(x, y);
  }

  /// Three independent gaussian() values (x, y, z drawn in that order).
  Eigen::Vector3d gaussianVector() {
    const double x = gaussian();
    const double y = gaussian();
    const double z = gaussian();
    return Eigen::Vector3d(x, y, z);
  }

 private:
  std::mt19937 engine_;
};

}  // namespace asr_ism
