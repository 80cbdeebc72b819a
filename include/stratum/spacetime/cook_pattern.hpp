#pragma once
/// Cook-style time-slot tables (LECTURE.md §8): the lecture shows Cook's
/// 4×4 pattern, a fixed "prototype" assignment of the 16 time slots to the
/// 16 strata that is jittered for every pixel (Cook, Porter, Carpenter 1984,
/// "Distributed ray tracing"; Cook 1986, "Stochastic sampling in computer
/// graphics"). Cook gives no construction rule; the table looks random, but
/// it has one rare property (found by comparison with 20000 random
/// permutations): no two strata that share an edge get consecutive slots,
/// i.e. edge neighbours differ by at least 2 slots (3% of random
/// permutations achieve that), and its mean neighbour difference (6.9 slots)
/// is in the top 3% (random: (m²+1)/3 = 5.7).
///
/// Generalization to other orders, keeping the spirit (random-looking, but
/// nearby strata far apart in time): a seeded random permutation, repaired
/// by random swaps until every pair of edge-adjacent strata, on the torus
/// (so the property survives tiling pixels), differs by at least
/// δ(m) = m slots (one m-th of the shutter) for m ≥ 5, and by ⌈m/2⌉ for
/// m ≤ 3 (the most that exists there). The seed is fixed: like Cook's, the
/// table is a prototype, the same for every pixel; per-pixel variety comes
/// from the jitter. m = 4 returns the slide's table itself (δ = 2 as
/// printed, not across the torus: its first and last rows hold 6 and 5 in
/// column 0).
#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include "stratum/spacetime/time_assignment.hpp"
#include "stratum/util/hash.hpp"

namespace stratum {

/// The lecture's 4×4 Cook pattern (rows top to bottom).
inline constexpr std::array<std::uint32_t, 16> slide_cook_pattern = {6,  10, 2, 13, 3, 14, 12, 8,
                                                                     15, 0,  7, 11, 5, 9,  4,  1};

/// The smallest slot difference cook_slots(m) guarantees between strata
/// sharing an edge (on the torus, except for the slide's m = 4 table).
constexpr std::uint32_t cook_separation(std::uint32_t m) noexcept { return m == 4 ? 2 : m >= 5 ? m : (m + 1) / 2; }

/// The Cook-style table of order m (see above). Deterministic.
inline SlotTable cook_slots(std::uint32_t m) {
  require_slot_order(m);
  if (m == 4) {
    SlotTable table{4, std::vector<std::uint32_t>(slide_cook_pattern.begin(), slide_cook_pattern.end())};
    return table;
  }
  constexpr std::uint64_t seed = 0x436f'6f6b'3139'3834ULL;  // fixed: the prototype
  SlotTable table = random_slots(m, seed);
  if (m == 1) return table;
  const auto delta = static_cast<std::int64_t>(cook_separation(m));
  const std::size_t cells = table.slots.size();
  // Shortfall of the cell at `k` against its four torus neighbours.
  const auto shortfall = [&](std::size_t k) {
    const std::uint32_t r = static_cast<std::uint32_t>(k / m), c = static_cast<std::uint32_t>(k % m);
    const std::int64_t slot = table.slots[k];
    const std::uint32_t neighbours[4][2] = {
        {r, (c + 1) % m}, {r, (c + m - 1) % m}, {(r + 1) % m, c}, {(r + m - 1) % m, c}};
    std::int64_t total = 0;
    for (const auto& n : neighbours) {
      const std::int64_t gap = slot - static_cast<std::int64_t>(table(n[0], n[1]));
      total += std::max<std::int64_t>(0, delta - (gap < 0 ? -gap : gap));
    }
    return total;
  };
  const std::uint64_t key = hash64(seed, 0x5357'4150ULL);
  std::uint64_t draw = 0;
  for (unsigned pass = 0;; ++pass) {
    bool clean = true;
    for (std::size_t a = 0; a < cells; ++a) {
      if (shortfall(a) == 0) continue;
      clean = false;
      // Swap with random cells until a swap lowers the pair's shortfall.
      for (unsigned attempt = 0; attempt < 256; ++attempt) {
        const std::size_t b = uniform_below(cells, key, draw++);
        if (b == a) continue;
        const std::int64_t before = shortfall(a) + shortfall(b);
        std::swap(table.slots[a], table.slots[b]);
        if (shortfall(a) + shortfall(b) < before) break;
        std::swap(table.slots[a], table.slots[b]);
      }
    }
    if (clean) return table;
    if (pass == 100000) throw std::logic_error("cook_slots: the repair did not converge");  // never seen
  }
}

}  // namespace stratum
