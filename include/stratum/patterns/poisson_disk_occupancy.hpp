#pragma once
/// Which cells of the plane's background grid hold a sample, for stratum's
/// maximal Poisson-disk sampler (poisson_disk_grid.hpp): one byte per cell,
/// read eight cells at a time. A Bridson step (Bridson 2007) and a
/// completion visit (Ebeida et al. 2012) both gather the samples of a block
/// of cells around a centre; about two cells in three are empty at the end
/// of Bridson's phase, so reading a row of the block as one word and
/// visiting only its occupied cells does a third of the work of visiting
/// every cell.
#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

#include "stratum/util/error.hpp"

namespace stratum::poisson_detail {

/// One byte per cell of a row-major grid (rows of stride 1 along x): 1
/// where the cell holds a sample.
class CellOccupancy {
 public:
  /// `cells` cells, all empty; eight bytes of slack so that a row read
  /// that starts at the last cell stays inside the array.
  void reset(std::size_t cells) { bytes_.assign(cells + 8, 0); }
  void mark(std::int64_t index) noexcept { bytes_[static_cast<std::size_t>(index)] = 1; }
  bool occupied(std::int64_t index) const noexcept { return bytes_[static_cast<std::size_t>(index)] != 0; }

  /// Bit i (i < width ≤ 8) set iff cell first + i is occupied. The eight
  /// bytes are 0 or 1; the multiplier moves byte i to bit 56 + i, and its
  /// other partial products land at distinct bits (no carries) either
  /// below 56 or beyond 63.
  std::uint64_t row(std::int64_t first, std::uint64_t byte_mask) const noexcept {
    std::uint64_t word = 0;
    const std::uint8_t* bytes = bytes_.data() + first;
    if constexpr (std::endian::native == std::endian::little) {
      std::memcpy(&word, bytes, sizeof word);
    } else {
      for (unsigned i = 0; i < 8; ++i) word |= std::uint64_t{bytes[i]} << (8 * i);
    }
    return ((word & byte_mask) * 0x0102'0408'1020'4080ULL) >> 56;
  }

 private:
  std::vector<std::uint8_t> bytes_;
};

/// A set of at most 64 cells around a centre cell, as runs of at most 8
/// consecutive cells of a row; bit b of a mask stands for the cell at
/// linear offset offset(b) from the centre. Bits follow the cells in
/// row-major order.
class CellPattern {
 public:
  CellPattern() = default;

  /// The cells (x, y) (offsets from the centre, any order, no repeats) of
  /// a grid whose rows are `row_stride` cells apart.
  CellPattern(std::vector<std::pair<std::int64_t, std::int64_t>> cells, std::int64_t row_stride) {
    require(cells.size() <= 64, "cells", cells.size(), "a cell pattern holds at most 64 cells");
    std::sort(cells.begin(), cells.end(), [](const auto& a, const auto& b) {
      return a.second != b.second ? a.second < b.second : a.first < b.first;
    });
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const auto [x, y] = cells[i];
      const std::int64_t linear = x + y * row_stride;
      offsets_[i] = linear;
      const bool extends = run_count_ > 0 && i > 0 && cells[i - 1].second == y && cells[i - 1].first + 1 == x &&
                           runs_[run_count_ - 1].width < 8;
      if (extends) {
        ++runs_[run_count_ - 1].width;
      } else {
        require(run_count_ < max_runs, "cells", cells.size(), "a cell pattern holds at most 16 runs");
        runs_[run_count_++] = Run{linear, 1, static_cast<unsigned>(i), 0};
      }
    }
    for (std::size_t k = 0; k < run_count_; ++k)
      runs_[k].byte_mask = runs_[k].width == 8 ? ~std::uint64_t{0} : (std::uint64_t{1} << (8 * runs_[k].width)) - 1;
    size_ = cells.size();
  }

  std::size_t size() const noexcept { return size_; }
  std::int64_t offset(unsigned bit) const noexcept { return offsets_[bit]; }

  /// The pattern's occupied cells around the cell `centre`.
  std::uint64_t occupied(const CellOccupancy& occupancy, std::int64_t centre) const noexcept {
    std::uint64_t mask = 0;
    for (std::size_t k = 0; k < run_count_; ++k)
      mask |= occupancy.row(centre + runs_[k].first, runs_[k].byte_mask) << runs_[k].shift;
    return mask;
  }

  /// The bits whose cell (x, y) satisfies `keep(x, y)`; needs the same
  /// row stride as construction to decode offsets.
  template <class Keep>
  std::uint64_t bits_where(std::int64_t row_stride, Keep keep) const {
    std::uint64_t bits = 0;
    for (std::size_t b = 0; b < size_; ++b) {
      // |x| < row_stride / 2, so the nearest row is y.
      const std::int64_t y = (offsets_[b] + (offsets_[b] >= 0 ? row_stride / 2 : -(row_stride / 2))) / row_stride;
      if (keep(offsets_[b] - y * row_stride, y)) bits |= std::uint64_t{1} << b;
    }
    return bits;
  }

 private:
  struct Run {
    std::int64_t first;  // offset of the run's first cell
    unsigned width;
    unsigned shift;  // bit of the run's first cell
    std::uint64_t byte_mask;
  };
  static constexpr std::size_t max_runs = 16;
  std::array<Run, max_runs> runs_{};
  std::size_t run_count_ = 0;
  std::array<std::int64_t, 64> offsets_{};
  std::size_t size_ = 0;
};

}  // namespace stratum::poisson_detail
