#pragma once
/// Bridson's phase of stratum's maximal Poisson-disk sampler in the plane
/// (Bridson 2007, "Fast Poisson disk sampling in arbitrary dimensions";
/// the engine is poisson_disk_grid.hpp): candidates are screened eight at
/// a time in float vectors before the exact tests, and the set is the one
/// the sequential kernel makes, bit for bit.
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "stratum/patterns/poisson_disk_candidates.hpp"
#include "stratum/patterns/poisson_disk_grid.hpp"
#include "stratum/util/hash.hpp"

namespace stratum::poisson_detail {

// Phase 1 in the plane, eight candidates at a time. A step lists the
// samples of the 7×7 cells around p (which shadow most of its annulus) as
// float offsets from p, draws eight candidates in float
// (annulus_offsets_2d_float) and tests them against every listed sample
// at once, one vector operation per sample for the eight. A candidate
// whose squared distance to a listed sample is below r²·(1 - 4·10^-4) in
// float is surely closer than r: offsets err by less than 10^-5·2r
// (annulus_offsets_2d_float), so squared distances below r² err by less
// than 5·10^-5·r² (offsets from p keep errors relative to r, whatever r
// is). A candidate surely outside the square is shut too. Every other
// candidate, in order, is drawn again in double exactly as
// grow_sequential draws it and meets the exact tests (the cube, then
// is_free_plane, is_free's test); if a sample rejects it, that sample
// joins the list and shadows the batch's later candidates too. A
// candidate is thus placed iff grow_sequential would place it, and the
// first one placed is the same: the sets are equal bit for bit. Most
// steps retire their point after k failures, and then every batch is
// usually shut by the screen alone: no double arithmetic, no grid look-up.
template <unsigned D>
[[gnu::always_inline]] inline void CompactPoissonDisk<D>::grow_plane() {
  static_assert(D == 2);
  using floats8 = float __attribute__((vector_size(32)));
  using mask8 = int __attribute__((vector_size(32)));
  const std::array<double, 512>& circle = unit_circle_256();
  const std::array<float, 512>& circle_float = unit_circle_256_float();
  std::int64_t c[2];
  std::vector<std::uint32_t> active = start();
  const std::uint64_t step_key = hash64(seed_, tag_candidate);
  const std::size_t capacity = shadow_capacity_;
  float* const wx = shadows_.data();
  float* const wy = wx + capacity;
  const float surely2 = static_cast<float>(r2_ * (1 - shadow_margin));
  const float r_float = static_cast<float>(r_);
  const mask8 lane_index = {0, 1, 2, 3, 4, 5, 6, 7};
  const double outside_margin = periodic_ ? std::numeric_limits<double>::infinity() : 0x1.0p-20 + 1e-4 * r_;
  // Lanes that are still open, one bit each: the lanes (0 or -1) narrowed
  // to bytes, then gathered as in CellOccupancy::row.
  const auto open_lanes = [](const mask8& shut) {
    if constexpr (std::endian::native == std::endian::little) {
      using bytes8 = signed char __attribute__((vector_size(8)));
      const bytes8 narrow = __builtin_convertvector(shut, bytes8);
      std::uint64_t word;
      std::memcpy(&word, &narrow, sizeof word);
      const std::uint64_t shut_bits = ((word & 0x0101'0101'0101'0101ULL) * 0x0102'0408'1020'4080ULL) >> 56;
      return static_cast<unsigned>(~shut_bits & 0xffu);
    } else {
      unsigned open = 0;
      for (unsigned lane = 0; lane < 8; ++lane) open |= unsigned(shut[lane] == 0) << lane;
      return open;
    }
  };
  const auto all_shut = [](const mask8& shut) {  // lanes are 0 or -1
    std::uint64_t words[4];
    std::memcpy(words, &shut, sizeof words);
    return (words[0] & words[1] & words[2] & words[3]) == ~std::uint64_t{0};
  };
  for (std::uint64_t step = 0; !active.empty(); ++step) {
    const std::uint64_t key = hash64(step_key, step);
    const std::size_t pick = uniform_below(active.size(), key, tag_pick);
    const double* p_row = points_.data() + std::size_t(active[pick]) * 2;
    const double p[2] = {p_row[0], p_row[1]};
    for (unsigned j = 0; j < 2; ++j) c[j] = axis_cell(p[j]);
    const std::int64_t centre = cell_index(c);
    std::size_t count = 0;  // the samples of the block's occupied cells
    for (std::uint64_t bits = block_pattern_.occupied(occupancy_, centre); bits != 0; bits &= bits - 1) {
      const double* q = cell(centre + block_pattern_.offset(static_cast<unsigned>(std::countr_zero(bits))));
      wx[count] = static_cast<float>(q[0] - p[0]);
      wy[count] = static_cast<float>(q[1] - p[1]);
      ++count;
    }
    // Offsets that put a candidate surely outside the square (never on the
    // torus): a float offset errs by less than 2·10^-5·r and a bound
    // rounded to float by less than 10^-7, both well inside the margin, so
    // a candidate shut so fails the exact test too.
    float low[2], high[2];
    for (unsigned j = 0; j < 2; ++j) {
      low[j] = static_cast<float>(-p[j] - outside_margin);
      high[j] = static_cast<float>(1 - p[j] + outside_margin);
    }
    bool placed = false;
    for (unsigned first = 0; first < candidates_ && !placed; first += 8) {
      floats8 ox, oy;
      annulus_offsets_2d_float(r_float, key, first, ox, oy, circle_float);
      // Lanes that cannot take a sample: past the last candidate, surely
      // outside the square, or surely closer than r to a listed sample.
      mask8 shut = (lane_index >= static_cast<int>(candidates_ - first)) | (ox < low[0]) | (ox >= high[0]) |
                   (oy < low[1]) | (oy >= high[1]);
      for (std::size_t b = 0; b < count; ++b) {
        const floats8 dx = wx[b] - ox, dy = wy[b] - oy;
        shut |= dx * dx + dy * dy < surely2;
      }
      if (all_shut(shut)) continue;  // the usual case
      for (unsigned open = open_lanes(shut); open != 0;) {
        const unsigned lane = static_cast<unsigned>(std::countr_zero(open));
        open &= open - 1;
        double offset[2], unwrapped[2], wrapped[2];
        annulus_offset_2d(r_, key, first + lane, offset, circle);
        bool inside = true;
        for (unsigned j = 0; j < 2; ++j) {
          unwrapped[j] = p[j] + offset[j];
          if (!periodic_) inside &= (unwrapped[j] >= 0.0) & (unwrapped[j] < 1.0);
        }
        if (!inside) continue;
        wrap(unwrapped, wrapped, c);
        double hit[2];
        if (is_free_plane(wrapped, cell_index(c), hit)) {
          active.push_back(static_cast<std::uint32_t>(points_.size() / 2));
          add(wrapped, c);
          placed = true;
          break;
        }
        // The rejecter, as its image nearest to this candidate, shadows
        // the later candidates too.
        float image[2];
        for (unsigned j = 0; j < 2; ++j)
          image[j] = static_cast<float>(nearest_image(hit[j], unwrapped[j], wrapped[j]) - p[j]);
        if (count < capacity) {
          wx[count] = image[0];
          wy[count] = image[1];
          ++count;
        }
        const floats8 dx = image[0] - ox, dy = image[1] - oy;
        shut |= dx * dx + dy * dy < surely2;
        open &= open_lanes(shut);
      }
    }
    if (!placed) {
      active[pick] = active.back();
      active.pop_back();
    }
  }
}

}  // namespace stratum::poisson_detail
