#pragma once
/// Space-time patterns (LECTURE.md §8): samples complete in space, one per
/// stratum of an m×m jittered grid, but incomplete in time: the m² strata
/// share the shutter interval, each taking one of m² time slots. Time must be
/// decorrelated from space, so that nearby samples in space differ greatly
/// in time (Cook, Porter, Carpenter 1984, "Distributed ray tracing"; Cook
/// 1986, "Stochastic sampling in computer graphics"). The assignment of slots
/// to strata is a SlotTable: random (this file), Cook-style
/// (cook_pattern.hpp) or a pan-diagonal magic square (magic_square.hpp).
///
/// Orientation: tables are printed, like the lecture's slide, row 0 first
/// ("top"). Row r is the stratum y ∈ [r/m, (r+1)/m): raster order, y growing
/// downwards as in image and pixel coordinates, so the slide's top-left
/// entry is the stratum at the origin. Column c is x ∈ [c/m, (c+1)/m).
#include <cstdint>
#include <utility>
#include <vector>

#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"
#include "stratum/util/real.hpp"

namespace stratum {

/// The time slot of each stratum of an m×m grid, row-major: a permutation
/// of 0 .. m²−1.
struct SlotTable {
  /// Largest order: m² slots must fit in 32 bits.
  static constexpr std::uint32_t max_order = 65535;

  std::uint32_t order = 0;
  std::vector<std::uint32_t> slots;

  std::uint32_t operator()(std::uint32_t row, std::uint32_t column) const noexcept {
    return slots[static_cast<std::size_t>(row) * order + column];
  }
  std::uint32_t& operator()(std::uint32_t row, std::uint32_t column) noexcept {
    return slots[static_cast<std::size_t>(row) * order + column];
  }
  std::uint64_t size() const noexcept { return std::uint64_t{order} * order; }

  /// Are the entries a permutation of 0 .. m²−1?
  bool is_permutation() const {
    if (slots.size() != size()) return false;
    std::vector<bool> seen(slots.size(), false);
    for (std::uint32_t slot : slots) {
      if (slot >= seen.size() || seen[slot]) return false;
      seen[slot] = true;
    }
    return true;
  }
};

/// Throws unless 1 ≤ m ≤ SlotTable::max_order.
inline void require_slot_order(std::uint64_t m) {
  require(m >= 1 && m <= SlotTable::max_order, "m", m, "the grid order must be in [1, 65535]");
}

/// A uniformly random assignment: a Fisher–Yates shuffle of the m² slots,
/// driven by counter-based randomness (a function of the seed only).
inline SlotTable random_slots(std::uint32_t m, std::uint64_t seed) {
  require_slot_order(m);
  SlotTable table{m, std::vector<std::uint32_t>(static_cast<std::size_t>(m) * m)};
  for (std::size_t k = 0; k < table.slots.size(); ++k) table.slots[k] = static_cast<std::uint32_t>(k);
  const std::uint64_t key = hash64(seed, 0x5354'5241'4e44ULL);
  for (std::size_t k = table.slots.size(); k > 1; --k) {
    const std::uint64_t pick = uniform_below(k, key, k);
    std::swap(table.slots[k - 1], table.slots[pick]);
  }
  return table;
}

/// The n = m² points (x, y, t) of a space-time pattern: point
/// index = row·m + column lies in its stratum, x = (column + u)/m,
/// y = (row + v)/m, and in its time slot, t = (slot + w)/m², with u, v, w
/// uniform jitter from (seed, index, dimension). Index-addressable.
class SpaceTimePattern {
 public:
  SpaceTimePattern(SlotTable table, std::uint64_t seed)
      : table_(std::move(table)), key_(hash64(seed, 0x5354'4a49'54ULL)) {
    require(table_.order >= 1 && table_.is_permutation(), "table", table_.order,
            "a slot table must hold a permutation of 0 .. m^2 - 1");
  }

  const SlotTable& table() const noexcept { return table_; }
  std::uint64_t size() const noexcept { return table_.size(); }

  /// Coordinate `dim` (0: x, 1: y, 2: t) of point `index` < m².
  template <class Real = double>
  Real sample(std::uint64_t index, unsigned dim) const noexcept {
    const std::uint64_t m = table_.order;
    const double jitter = uniform01(key_, index, dim);
    const std::uint64_t column = index % m, row = index / m;  // the slot's place in the m x m square
    double value;
    if (dim == 0) value = (static_cast<double>(column) + jitter) / static_cast<double>(m);
    else if (dim == 1) value = (static_cast<double>(row) + jitter) / static_cast<double>(m);
    else value = (static_cast<double>(table_.slots[index]) + jitter) / static_cast<double>(m * m);
    return to_unit<Real>(value < one_minus_epsilon_double ? value : one_minus_epsilon_double);
  }

 private:
  SlotTable table_;
  std::uint64_t key_;
};

}  // namespace stratum
