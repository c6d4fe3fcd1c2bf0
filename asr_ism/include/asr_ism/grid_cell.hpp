#pragma once

#include <cmath>
#include <cstdint>

namespace asr_ism {

/// Coordinates within this many cells below a border count as on it. Poses derived from one
/// another through demonstrated relations often lie exactly on a border of a grid anchored at one
/// of them (objects 1.5 bins apart), where the last bit of rounding, which differs with where the
/// world frame lies, would put them on either side; nudged, they fall on one side in every frame.
/// Far above the rounding of a coordinate in cells (1e-13 m for poses 1 km away: 1e-11 of a 1 cm
/// cell), far below any measured offset.
constexpr double kGridBorderNudge = 1e-9;

/// The index of the cell of size `cell_size` that holds `coordinate`, the same on either side of
/// rounding at a border.
inline std::int64_t gridCell(double coordinate, double cell_size) {
  return static_cast<std::int64_t>(std::floor(coordinate / cell_size + kGridBorderNudge));
}

}  // namespace asr_ism
