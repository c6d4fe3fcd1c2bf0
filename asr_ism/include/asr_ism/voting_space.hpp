#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace asr_ism {

/// A sparse 3-D accumulator: points (vote positions) sorted into cubic bins of edge `bin_size`.
/// Bins exist only where points fall; a hash of packed cell indices finds a bin's neighbours.
/// Cells are packed relative to the lowest occupied one, so what limits the space is how far
/// its points spread, not how far they lie from the origin.
class VotingSpace {
 public:
  struct Bin {
    std::uint64_t key;    // packed cell index, relative to the lowest cell
    std::uint32_t begin;  // range of order() holding this bin's points
    std::uint32_t end;
  };

  /// Sorts the n points (x[i], y[i], z[i]) into bins. Throws InputError for a point that is not
  /// finite or more than 2^60 bins from the origin, and for points spread over more than
  /// maxSpread() along an axis.
  VotingSpace(double bin_size, const double* x, const double* y, const double* z, std::size_t n);

  /// Point indices sorted by bin (by cell index, x first, then y, then z), then by xOrder(x),
  /// then by index.
  const std::vector<std::uint32_t>& order() const { return order_; }
  /// The non-empty bins, sorted by packed cell index.
  const std::vector<Bin>& bins() const { return bins_; }

  /// Writes the indices of the non-empty bins among the 27 cells around bin `bin` (itself
  /// included) to `neighbours`; returns how many there are.
  int neighbourBins(std::size_t bin, std::array<int, 27>& neighbours) const;

  /// x at the resolution points are sorted by within a bin: 1e-8 bins. Points nearer than that
  /// keep their index order, so that rounding of their coordinates (a rigid motion of them
  /// all) cannot reorder them.
  static std::int64_t xOrder(double x, double bin_size);
  /// The integer cell of a coordinate.
  static std::int64_t cellOf(double coordinate, double bin_size);
  /// How far apart along one axis points of one space may lie with bins of `bin_size`.
  static double maxSpread(double bin_size);

 private:
  int findBin(std::uint64_t key) const;

  std::vector<std::uint32_t> order_;
  std::vector<Bin> bins_;
  std::vector<std::int32_t> table_;  // open addressing: bin index or -1
  std::uint64_t table_mask_ = 0;
};

}  // namespace asr_ism
