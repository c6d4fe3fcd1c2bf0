#include "asr_ism/voting_space.hpp"

#include <gtest/gtest.h>

#include <set>

#include "asr_ism/common_types.hpp"

namespace asr_ism {
namespace {

TEST(VotingSpace, PointsOnBinBordersOrWithinRoundingBelowThemGoToTheUpperBin) {
  // Values exactly representable in binary so that "on the border" means exactly on it. Within
  // 1e-9 bins below a border counts as on it (asr_ism/grid_cell.hpp): there rounding, which
  // differs with where the world frame lies, would decide.
  const double size = 0.125;
  std::vector<double> x = {0.0, size - 1e-6, size, -1e-6, -size, size - 1e-12, -1e-12};
  std::vector<double> y(x.size(), 0.0), z(x.size(), 0.0);
  EXPECT_EQ(VotingSpace::cellOf(0.0, size), 0);
  EXPECT_EQ(VotingSpace::cellOf(size - 1e-6, size), 0);
  EXPECT_EQ(VotingSpace::cellOf(size, size), 1);
  EXPECT_EQ(VotingSpace::cellOf(-1e-6, size), -1);
  EXPECT_EQ(VotingSpace::cellOf(-size, size), -1);
  EXPECT_EQ(VotingSpace::cellOf(size - 1e-12, size), 1);
  EXPECT_EQ(VotingSpace::cellOf(-1e-12, size), 0);
  const VotingSpace space(size, x.data(), y.data(), z.data(), x.size());
  ASSERT_EQ(space.bins().size(), 3u);  // cells -1, 0, 1
}

TEST(VotingSpace, NeighbourhoodHoldsTheAdjacentCellsOnly) {
  // One point per cell of a 5x1x1 row of cells, plus a diagonal neighbour.
  std::vector<double> x = {0.05, 0.15, 0.25, 0.35, 0.45, 0.25};
  std::vector<double> y = {0.05, 0.05, 0.05, 0.05, 0.05, 0.15};
  std::vector<double> z = {0.05, 0.05, 0.05, 0.05, 0.05, 0.15};
  const VotingSpace space(0.1, x.data(), y.data(), z.data(), x.size());
  ASSERT_EQ(space.bins().size(), 6u);
  // Find the bin of the point at x = 0.25 (index 2).
  std::size_t middle = 0;
  for (std::size_t b = 0; b < space.bins().size(); ++b) {
    if (space.order()[space.bins()[b].begin] == 2)
      middle = b;
  }
  std::array<int, 27> neighbours;
  const int count = space.neighbourBins(middle, neighbours);
  std::set<std::uint32_t> points;
  for (int n = 0; n < count; ++n) {
    const auto& bin = space.bins()[neighbours[n]];
    for (auto i = bin.begin; i < bin.end; ++i)
      points.insert(space.order()[i]);
  }
  EXPECT_EQ(points, (std::set<std::uint32_t>{1, 2, 3, 5}));
}

TEST(VotingSpace, SortsPointsByBinDeterministically) {
  std::vector<double> x = {0.31, 0.01, 0.02, 0.33, 0.01};
  std::vector<double> y(5, 0.0), z(5, 0.0);
  const VotingSpace space(0.1, x.data(), y.data(), z.data(), x.size());
  EXPECT_EQ(space.order(), (std::vector<std::uint32_t>{1, 4, 2, 0, 3}));
}

TEST(VotingSpace, RejectsPointsOutsideItsRange) {
  std::vector<double> x = {0.0, 1e9}, y = {0.0, 0.0}, z = {0.0, 0.0};
  EXPECT_THROW(VotingSpace(0.1, x.data(), y.data(), z.data(), 2), InputError);
  std::vector<double> huge = {1e300};
  EXPECT_THROW(VotingSpace(0.1, huge.data(), y.data(), z.data(), 1), InputError);
}

// Cells are packed relative to the lowest: far from the origin, points close together fit, and
// the limit is how far apart they lie.
TEST(VotingSpace, HoldsPointsFarFromTheOriginThatLieClose) {
  const double bin = 0.1;
  std::vector<double> x = {1e7, 1e7 + 0.05, 1e7 + 0.15}, y = {-3e6, -3e6, -3e6}, z(3, 0.0);
  const VotingSpace space(bin, x.data(), y.data(), z.data(), x.size());
  EXPECT_EQ(space.bins().size(), 2u);
  std::array<int, 27> neighbours;
  EXPECT_EQ(space.neighbourBins(0, neighbours), 2);
  std::vector<double> apart = {0.0, 0.999 * VotingSpace::maxSpread(bin)};
  EXPECT_NO_THROW(VotingSpace(bin, apart.data(), y.data(), z.data(), 2));
  apart[1] = 1.001 * VotingSpace::maxSpread(bin);
  EXPECT_THROW(VotingSpace(bin, apart.data(), y.data(), z.data(), 2), InputError);
}

}  // namespace
}  // namespace asr_ism
