#include "stratum/patterns/poisson_disk_grid.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "stratum/util/hash.hpp"

namespace stratum::poisson_detail {
namespace {

TEST(CompactPoissonDisk, GridGeometry) {
  // r = 0.1 in 2D: ⌈√2/0.1⌉ = 15 cells of side 1/15 ≤ r/√2, reach ⌈1.5⌉ = 2,
  // padded to 3 for grow_plane's 7×7 block.
  EXPECT_EQ(CompactPoissonDisk<2>::cells_per_axis(0.1), 15u);
  EXPECT_EQ(CompactPoissonDisk<2>::padding(0.1), 3);
  EXPECT_DOUBLE_EQ(CompactPoissonDisk<2>::grid_bytes(0.1), 21.0 * 21.0 * 2 * 8);
  // r = 0.9: reach ⌈0.9·⌈√2/0.9⌉⌉ = ⌈1.8⌉ = 2, also padded to 3.
  EXPECT_EQ(CompactPoissonDisk<2>::padding(0.9), 3);
  // 3D keeps the reach: ⌈0.1·⌈√3/0.1⌉⌉ = ⌈1.8⌉ = 2.
  EXPECT_EQ(CompactPoissonDisk<3>::padding(0.1), 2);
  // r·g = 1 exactly in 1D: reach one cell, not two.
  EXPECT_EQ(CompactPoissonDisk<1>::cells_per_axis(0.25), 4u);
  EXPECT_EQ(CompactPoissonDisk<1>::padding(0.25), 1);
}

// The engine's output is the maximal set PoissonDisk returns for d <= 4; its
// properties are tested in poisson_disk_test.cpp. Here: samples stay in the
// cube on the torus even when candidates wrap, and r = 1 leaves one sample.
TEST(CompactPoissonDisk, TorusWrapsIntoTheCube) {
  const auto points = CompactPoissonDisk<2>(0.2, 5, 30, true, 40).generate();
  for (double v : points) {
    EXPECT_GE(v, 0.0);
    EXPECT_LT(v, 1.0);
  }
  EXPECT_EQ(CompactPoissonDisk<3>(1.0, 5, 30, true, 40).generate().size(), 3u);  // torus diameter √3/2 < 1
}

// The plane's batched Bridson kernels (float screen, eight candidates at a
// time; portable and AVX2 builds) place exactly the samples that the
// one-candidate-at-a-time kernel places: the same maximal set, bit for bit,
// on the square and the torus, for candidate counts that fill the batches
// or not.
TEST(CompactPoissonDisk, BatchedKernelsEqualTheSequentialKernel) {
  for (double radius : {0.008, 0.05, 0.3})
    for (bool periodic : {false, true})
      for (unsigned candidates : {1u, 7u, 30u, 33u})
        for (std::uint64_t seed : {1ull, 2ull}) {
          const auto run = [&](BridsonKernel kernel) {
            return CompactPoissonDisk<2>(radius, seed, candidates, periodic, 40, kernel).generate();
          };
          const std::vector<double> sequential = run(BridsonKernel::sequential);
          ASSERT_GT(sequential.size(), 2u);
          EXPECT_EQ(run(BridsonKernel::batched), sequential)
              << "r=" << radius << " periodic=" << periodic << " k=" << candidates << " seed=" << seed;
          EXPECT_EQ(run(BridsonKernel::fastest), sequential)
              << "r=" << radius << " periodic=" << periodic << " k=" << candidates << " seed=" << seed;
        }
}

// A cell pattern read from the occupancy bytes names exactly the occupied
// cells among its cells (brute force over every cell of a random grid),
// for patterns with runs of every width 1..8 and longer rows that must be
// split into runs of at most 8.
TEST(CellPattern, MasksNameExactlyTheOccupiedCells) {
  constexpr std::int64_t side = 23, margin = 6;
  std::vector<std::pair<std::int64_t, std::int64_t>> cells;
  for (std::int64_t y = -margin; y <= margin; ++y) {
    const std::int64_t width = (y + margin) % 12 + 1;  // 1..12 cells
    for (std::int64_t x = -3; x < -3 + width && cells.size() < 64; ++x) cells.emplace_back(x, y);
  }
  ASSERT_EQ(cells.size(), 64u);
  const CellPattern pattern(cells, side);
  ASSERT_EQ(pattern.size(), 64u);
  for (std::uint64_t seed : {1ull, 2ull, 3ull}) {
    CellOccupancy occupancy;
    occupancy.reset(side * side);
    std::vector<bool> truth(side * side, false);
    for (std::int64_t index = 0; index < side * side; ++index)
      if (hash64(seed, static_cast<std::uint64_t>(index)) % 3 == 0) {
        occupancy.mark(index);
        truth[static_cast<std::size_t>(index)] = true;
      }
    for (std::int64_t cy = margin; cy < side - margin; ++cy)
      for (std::int64_t cx = margin; cx < side - margin; ++cx) {
        const std::int64_t centre = cx + cy * side;
        const std::uint64_t mask = pattern.occupied(occupancy, centre);
        std::uint64_t expected = 0;
        for (unsigned bit = 0; bit < 64; ++bit)
          if (truth[static_cast<std::size_t>(centre + pattern.offset(bit))]) expected |= std::uint64_t{1} << bit;
        ASSERT_EQ(mask, expected) << "seed " << seed << " centre " << cx << "," << cy;
      }
  }
  // Bits follow the cells in row-major order, and bits_where decodes them.
  std::int64_t previous = -side * side;
  for (unsigned bit = 0; bit < 64; ++bit) {
    EXPECT_GT(pattern.offset(bit), previous);
    previous = pattern.offset(bit);
  }
  const std::uint64_t row_zero = pattern.bits_where(side, [](std::int64_t, std::int64_t y) { return y == 0; });
  EXPECT_EQ(std::popcount(row_zero), 7);  // (0 + 6) % 12 + 1 cells in row 0
}

}  // namespace
}  // namespace stratum::poisson_detail
