#include "asr_ism/voting_space.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "asr_ism/common_types.hpp"
#include "asr_ism/grid_cell.hpp"

namespace asr_ism {
namespace {

constexpr int kCellBits = 21;
constexpr std::uint64_t kCellMask = (std::uint64_t{1} << kCellBits) - 1;

// Cells relative to the space's origin cell, each in [0, 2^kCellBits).
std::uint64_t packCell(std::int64_t cx, std::int64_t cy, std::int64_t cz) {
  return (static_cast<std::uint64_t>(cx) << (2 * kCellBits)) |
         (static_cast<std::uint64_t>(cy) << kCellBits) | static_cast<std::uint64_t>(cz);
}

std::int64_t unpackCell(std::uint64_t key, int shift) {
  return static_cast<std::int64_t>((key >> shift) & kCellMask);
}

std::uint64_t hashKey(std::uint64_t key) {
  // splitmix64 finaliser: spreads neighbouring cells over the table.
  key ^= key >> 30;
  key *= 0xbf58476d1ce4e5b9ULL;
  key ^= key >> 27;
  key *= 0x94d049bb133111ebULL;
  key ^= key >> 31;
  return key;
}

}  // namespace

std::int64_t VotingSpace::cellOf(double coordinate, double bin_size) {
  return gridCell(coordinate, bin_size);
}

std::int64_t VotingSpace::xOrder(double x, double bin_size) {
  return std::llround(x / (1e-8 * bin_size));
}

double VotingSpace::maxSpread(double bin_size) {
  // Cells are packed relative to the lowest, with one spare cell either side for neighbours;
  // points this far apart lie at most kCellMask - 3 cells apart.
  return static_cast<double>(kCellMask - 4) * bin_size;
}

VotingSpace::VotingSpace(double bin_size, const double* x, const double* y, const double* z,
                         std::size_t n) {
  // Far enough below 2^63 that a cell index and its neighbours' fit a signed 64-bit integer.
  const double max_cell = 0x1p60;
  std::vector<std::array<std::int64_t, 3>> cells(n);
  std::array<std::int64_t, 3> lowest = {0, 0, 0}, highest = {0, 0, 0}, origin;
  for (std::size_t i = 0; i < n; ++i) {
    const double coordinates[3] = {x[i], y[i], z[i]};
    for (int axis = 0; axis < 3; ++axis) {
      if (!std::isfinite(coordinates[axis])) {
        throw InputError("voting space: a vote position is not finite");
      }
      if (!(std::abs(coordinates[axis] / bin_size) < max_cell)) {
        std::ostringstream message;
        message << "voting space: a vote at coordinate " << coordinates[axis]
                << " m lies too far from the origin for bins of " << bin_size << " m";
        throw InputError(message.str());
      }
      const std::int64_t cell = cellOf(coordinates[axis], bin_size);
      cells[i][axis] = cell;
      lowest[axis] = i == 0 ? cell : std::min(lowest[axis], cell);
      highest[axis] = i == 0 ? cell : std::max(highest[axis], cell);
    }
  }
  for (int axis = 0; axis < 3; ++axis) {
    if (highest[axis] - lowest[axis] > static_cast<std::int64_t>(kCellMask) - 3) {
      std::ostringstream message;
      message << "voting space: votes spread over "
              << static_cast<double>(highest[axis] - lowest[axis]) * bin_size
              << " m along one axis, more than the " << maxSpread(bin_size) << " m bins of "
              << bin_size << " m can hold";
      throw InputError(message.str());
    }
    // Packed cells start at 1, so that the lowest cell's lower neighbour is 0, not negative.
    origin[axis] = lowest[axis] - 1;
  }
  struct Entry {
    std::uint64_t key;
    std::int64_t x;
    std::uint32_t index;
  };
  std::vector<Entry> entries(n);
  for (std::size_t i = 0; i < n; ++i) {
    entries[i] = {
        packCell(cells[i][0] - origin[0], cells[i][1] - origin[1], cells[i][2] - origin[2]),
        xOrder(x[i], bin_size), static_cast<std::uint32_t>(i)};
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    if (a.key != b.key)
      return a.key < b.key;
    if (a.x != b.x)
      return a.x < b.x;
    return a.index < b.index;
  });
  order_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    order_[i] = entries[i].index;
    if (i == 0 || entries[i].key != entries[i - 1].key) {
      bins_.push_back({entries[i].key, static_cast<std::uint32_t>(i), 0});
    }
    bins_.back().end = static_cast<std::uint32_t>(i + 1);
  }
  std::size_t table_size = 16;
  while (table_size < 2 * bins_.size()) {
    table_size *= 2;
  }
  table_.assign(table_size, -1);
  table_mask_ = table_size - 1;
  for (std::size_t b = 0; b < bins_.size(); ++b) {
    std::uint64_t slot = hashKey(bins_[b].key) & table_mask_;
    while (table_[slot] >= 0) {
      slot = (slot + 1) & table_mask_;
    }
    table_[slot] = static_cast<std::int32_t>(b);
  }
}

int VotingSpace::findBin(std::uint64_t key) const {
  for (std::uint64_t slot = hashKey(key) & table_mask_;; slot = (slot + 1) & table_mask_) {
    const std::int32_t bin = table_[slot];
    if (bin < 0 || bins_[bin].key == key) {
      return bin;
    }
  }
}

int VotingSpace::neighbourBins(std::size_t bin, std::array<int, 27>& neighbours) const {
  const std::uint64_t key = bins_[bin].key;
  const std::int64_t cx = unpackCell(key, 2 * kCellBits);
  const std::int64_t cy = unpackCell(key, kCellBits);
  const std::int64_t cz = unpackCell(key, 0);
  int count = 0;
  for (std::int64_t dx = -1; dx <= 1; ++dx) {
    for (std::int64_t dy = -1; dy <= 1; ++dy) {
      for (std::int64_t dz = -1; dz <= 1; ++dz) {
        const int found = findBin(packCell(cx + dx, cy + dy, cz + dz));
        if (found >= 0) {
          neighbours[count++] = found;
        }
      }
    }
  }
  return count;
}

}  // namespace asr_ism
