#include "stratum/spacetime/magic_square.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

namespace stratum {
namespace {

// Every row, column and broken diagonal in both directions sums to
// m(m²−1)/2, and the entries are a permutation of 0 .. m²−1.
void expect_pandiagonal_magic(const SlotTable& t) {
  const std::uint32_t m = t.order;
  const std::uint64_t sum = magic_sum(m);
  ASSERT_TRUE(t.is_permutation()) << m;
  for (std::uint32_t i = 0; i < m; ++i) {
    std::uint64_t row = 0, column = 0, diagonal = 0, anti = 0;
    for (std::uint32_t k = 0; k < m; ++k) {
      row += t(i, k);
      column += t(k, i);
      diagonal += t(k, (i + k) % m);
      anti += t(k, (i + m - k % m) % m);
    }
    ASSERT_EQ(row, sum) << "m=" << m << " row " << i;
    ASSERT_EQ(column, sum) << "m=" << m << " column " << i;
    ASSERT_EQ(diagonal, sum) << "m=" << m << " diagonal " << i;
    ASSERT_EQ(anti, sum) << "m=" << m << " antidiagonal " << i;
  }
}

TEST(MagicSquare, SlideSquareExactly) {
  const SlotTable t = pandiagonal_magic_square(4);
  const std::uint32_t slide[4][4] = {{15, 8, 5, 2}, {4, 3, 14, 9}, {10, 13, 0, 7}, {1, 6, 11, 12}};
  for (std::uint32_t r = 0; r < 4; ++r)
    for (std::uint32_t c = 0; c < 4; ++c) EXPECT_EQ(t(r, c), slide[r][c]);
  expect_pandiagonal_magic(t);
}

// All valid orders 4..64: odd orders prime to 3 (cyclic construction), odd
// multiples of 3 (balanced σ) and doubly even orders (antipodal σ).
TEST(MagicSquare, EveryValidOrderUpTo64IsPandiagonalMagic) {
  int built = 0;
  for (std::uint32_t m = 1; m <= 64; ++m) {
    if (!pandiagonal_magic_exists(m)) continue;
    expect_pandiagonal_magic(pandiagonal_magic_square(m));
    ++built;
  }
  EXPECT_EQ(built, 1 + 46);  // m = 1, and 4..64 without 6, 10, ..., 62 (15 orders)
}

TEST(MagicSquare, LargeOrdersToo) {
  for (std::uint32_t m : {99u, 100u, 128u, 243u, 255u}) expect_pandiagonal_magic(pandiagonal_magic_square(m));
}

TEST(MagicSquare, OrdersWithoutSquaresAreRefused) {
  for (std::uint32_t m : {0u, 2u, 3u, 6u, 10u, 14u, 66u}) {
    EXPECT_FALSE(pandiagonal_magic_exists(m) && m != 0) << m;
    try {
      pandiagonal_magic_square(m);
      FAIL() << m;
    } catch (const invalid_argument& e) {
      EXPECT_EQ(e.argument(), "m");
      EXPECT_NE(std::string(e.what()).find(std::to_string(m)), std::string::npos);
    }
  }
  EXPECT_TRUE(pandiagonal_magic_exists(1));
  EXPECT_TRUE(pandiagonal_magic_exists(9));
  EXPECT_TRUE(pandiagonal_magic_exists(12));
  EXPECT_EQ(magic_sum(4), 30u);
}

}  // namespace
}  // namespace stratum
