#include "asr_ism/portable_random.hpp"

namespace asr_ism {

double uniformUnit(std::mt19937& engine) {
  const std::uint64_t high = engine() >> 5;  // 27 bits
  const std::uint64_t low = engine() >> 6;   // 26 bits
  return static_cast<double>((high << 26) | low) * (1.0 / 9007199254740992.0);
}

std::uint32_t uniformBelow(std::mt19937& engine, std::uint32_t bound) {
  std::uint64_t product = static_cast<std::uint64_t>(engine()) * bound;
  auto low = static_cast<std::uint32_t>(product);
  if (low < bound) {
    // 2^32 mod bound of the 2^32 raw values would make the low results more likely: reject them.
    const std::uint32_t threshold = static_cast<std::uint32_t>(-bound) % bound;
    while (low < threshold) {
      product = static_cast<std::uint64_t>(engine()) * bound;
      low = static_cast<std::uint32_t>(product);
    }
  }
  return static_cast<std::uint32_t>(product >> 32);
}

}  // namespace asr_ism
