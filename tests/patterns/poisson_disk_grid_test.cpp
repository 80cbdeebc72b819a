#include "stratum/patterns/poisson_disk_grid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace stratum::poisson_detail {
namespace {

TEST(CompactPoissonDisk, GridGeometry) {
  // r = 0.1 in 2D: ⌈√2/0.1⌉ = 15 cells of side 1/15 ≤ r/√2, reach ⌈1.5⌉ = 2.
  EXPECT_EQ(CompactPoissonDisk<2>::cells_per_axis(0.1), 15u);
  EXPECT_EQ(CompactPoissonDisk<2>::padding(0.1), 2);
  EXPECT_DOUBLE_EQ(CompactPoissonDisk<2>::grid_bytes(0.1), 19.0 * 19.0 * 2 * 8);
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
  for (double radius : {0.008, 0.05})
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

}  // namespace
}  // namespace stratum::poisson_detail
