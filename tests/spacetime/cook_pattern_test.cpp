#include "stratum/spacetime/cook_pattern.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>

namespace stratum {
namespace {

// Smallest slot difference between strata sharing an edge; `torus`: also
// across the table's borders (as when pixels tile).
std::int64_t edge_separation(const SlotTable& t, bool torus) {
  const std::uint32_t m = t.order;
  std::int64_t best = static_cast<std::int64_t>(m) * m;
  for (std::uint32_t r = 0; r < m; ++r)
    for (std::uint32_t c = 0; c < m; ++c) {
      if (torus || c + 1 < m)
        best = std::min<std::int64_t>(best, std::llabs(std::int64_t{t(r, c)} - t(r, (c + 1) % m)));
      if (torus || r + 1 < m)
        best = std::min<std::int64_t>(best, std::llabs(std::int64_t{t(r, c)} - t((r + 1) % m, c)));
    }
  return best;
}

TEST(CookPattern, SlideTableExactly) {
  const SlotTable t = cook_slots(4);
  const std::uint32_t slide[4][4] = {{6, 10, 2, 13}, {3, 14, 12, 8}, {15, 0, 7, 11}, {5, 9, 4, 1}};
  for (std::uint32_t r = 0; r < 4; ++r)
    for (std::uint32_t c = 0; c < 4; ++c) EXPECT_EQ(t(r, c), slide[r][c]);
  // The property the generalization keeps: edge neighbours never get
  // consecutive slots (as printed; across the border 6 and 5 meet).
  EXPECT_EQ(edge_separation(t, false), 2);
  EXPECT_EQ(edge_separation(t, true), 1);
  EXPECT_EQ(cook_separation(4), 2u);
}

TEST(CookPattern, EdgeNeighboursAreFarApartInTime) {
  for (std::uint32_t m = 1; m <= 40; ++m) {
    if (m == 4) continue;
    const SlotTable t = cook_slots(m);
    ASSERT_TRUE(t.is_permutation()) << m;
    if (m >= 2) {
      EXPECT_GE(edge_separation(t, true), std::int64_t{cook_separation(m)}) << "m=" << m;
    }
  }
  EXPECT_EQ(cook_separation(5), 5u);
  EXPECT_EQ(cook_separation(3), 2u);
  const SlotTable big = cook_slots(128);
  EXPECT_GE(edge_separation(big, true), 128);
}

TEST(CookPattern, IsAFixedPrototype) {
  EXPECT_EQ(cook_slots(9).slots, cook_slots(9).slots);
  EXPECT_THROW(cook_slots(0), invalid_argument);
}

}  // namespace
}  // namespace stratum
