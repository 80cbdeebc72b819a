#include "stratum/spacetime/time_assignment.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "stratum/spacetime/cook_pattern.hpp"
#include "stratum/spacetime/magic_square.hpp"

namespace stratum {
namespace {

TEST(TimeAssignment, RandomSlotsArePermutationsFixedBySeed) {
  for (std::uint32_t m : {1u, 2u, 5u, 16u, 100u}) {
    const SlotTable t = random_slots(m, 3);
    EXPECT_EQ(t.order, m);
    EXPECT_TRUE(t.is_permutation()) << m;
    EXPECT_EQ(t.slots, random_slots(m, 3).slots);
  }
  EXPECT_NE(random_slots(16, 3).slots, random_slots(16, 4).slots);
  EXPECT_THROW(random_slots(0, 1), invalid_argument);
  EXPECT_THROW(random_slots(70000, 1), invalid_argument);
}

// Fisher–Yates is uniform: over 6000 shuffles of a 2×2 table (24
// permutations, 250 expected each) every permutation appears, within
// 250 ± 5σ (σ ≈ 15.5).
TEST(TimeAssignment, RandomSlotsAreUniform) {
  std::vector<int> counts(256, 0);
  for (std::uint64_t seed = 0; seed < 6000; ++seed) {
    const SlotTable t = random_slots(2, seed);
    ++counts[t.slots[0] * 64 + t.slots[1] * 16 + t.slots[2] * 4 + t.slots[3]];
  }
  int seen = 0;
  for (int c : counts)
    if (c > 0) {
      ++seen;
      EXPECT_NEAR(c, 250, 78);
    }
  EXPECT_EQ(seen, 24);
}

// Each point lies in its stratum (row = y, column = x) and in its slot.
TEST(TimeAssignment, PointsLieInTheirStratumAndSlot) {
  for (const SlotTable& table : {pandiagonal_magic_square(4), cook_slots(7), random_slots(16, 2)}) {
    const SpaceTimePattern pattern(table, 5);
    const std::uint32_t m = table.order;
    ASSERT_EQ(pattern.size(), std::uint64_t{m} * m);
    for (std::uint64_t i = 0; i < pattern.size(); ++i) {
      const double x = pattern.sample(i, 0), y = pattern.sample(i, 1), t = pattern.sample(i, 2);
      const std::uint32_t row = static_cast<std::uint32_t>(i / m), column = static_cast<std::uint32_t>(i % m);
      EXPECT_EQ(std::floor(x * m), column);
      EXPECT_EQ(std::floor(y * m), row);
      EXPECT_EQ(std::floor(t * m * m), table(row, column));
      EXPECT_EQ(pattern.sample<float>(i, 2), to_unit_float(t));
    }
  }
  // The slide's top-left stratum (row 0, column 0 = origin) takes slot 15.
  const SpaceTimePattern slide(pandiagonal_magic_square(4), 1);
  EXPECT_EQ(std::floor(slide.sample(0, 2) * 16), 15);
  EXPECT_LT(slide.sample(0, 0), 0.25);
  EXPECT_LT(slide.sample(0, 1), 0.25);
}

TEST(TimeAssignment, RejectsTablesThatAreNotPermutations) {
  EXPECT_THROW(SpaceTimePattern(SlotTable{2, {0, 1, 1, 3}}, 0), invalid_argument);
  EXPECT_THROW(SpaceTimePattern(SlotTable{2, {0, 1, 2}}, 0), invalid_argument);
}

}  // namespace
}  // namespace stratum
