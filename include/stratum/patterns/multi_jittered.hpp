#pragma once
/// Multi-jittered sampling (Chiu, Shirley, Wang 1994, "Multi-jittered
/// sampling", Graphics Gems IV): n = m × k points in [0, 1)², one in each
/// cell of an m × k grid of strata *and* one in each of the n equal
/// intervals of both coordinates (jittered and N-rooks at once, lecture §7).
/// The canonical arrangement puts the point of stratum (i, j) in fine
/// column i·k + j and fine row j·m + i; shuffling the fine columns inside
/// each coarse column and the fine rows inside each coarse row keeps both
/// properties and randomizes the set.
///
/// Correlated multi-jittered sampling (Kensler 2013, "Correlated
/// Multi-Jittered Sampling", Pixar Technical Memo 13-01) uses the same
/// shuffle for every coarse column (and row), which lowers discrepancy, and
/// draws the shuffles from a hash-based permutation permute(i, l, p), so any
/// sample is computed from its index alone. For any n it takes m = ⌊√(n·a)⌋
/// columns and k = ⌈n/m⌉ rows (aspect a), shuffles the sample index over n
/// and keeps y Latin over n intervals; when n = m·k the set is also Latin in
/// x and has one point per m × k stratum (as with n a square or m(m+1)).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "stratum/patterns/strata.hpp"
#include "stratum/util/fast_divider.hpp"

namespace stratum {

namespace multi_jittered_detail {
/// The all-ones mask of l − 1's bits (the power of two the walk hashes on).
constexpr std::uint32_t walk_mask(std::uint32_t l) noexcept {
  std::uint32_t w = l - 1;
  w |= w >> 1;
  w |= w >> 2;
  w |= w >> 4;
  w |= w >> 8;
  w |= w >> 16;
  return w;
}
/// Kensler's bijective hash on [0, w] walked until the value falls below l.
constexpr std::uint32_t kensler_walk(std::uint32_t i, std::uint32_t l, std::uint32_t w, std::uint32_t p) noexcept {
  do {
    i ^= p;
    i *= 0xe170893du;
    i ^= p >> 16;
    i ^= (i & w) >> 4;
    i ^= p >> 8;
    i *= 0x0929eb3fu;
    i ^= p >> 23;
    i ^= (i & w) >> 1;
    i *= 1u | p >> 27;
    i *= 0x6935fa69u;
    i ^= (i & w) >> 11;
    i *= 0x74dcb303u;
    i ^= (i & w) >> 2;
    i *= 0x9e501cc3u;
    i ^= (i & w) >> 2;
    i *= 0xc860a3dfu;
    i &= w;
    i ^= i >> 5;
  } while (i >= l);
  return i;
}
}  // namespace multi_jittered_detail

/// Kensler's (2013) hash-based permutation of {0, …, l-1} (his Listing 3):
/// a bijective hash on the next power of two, cycle-walking until the value
/// falls below l, then a rotation by p. p selects the permutation. The final
/// rotation (i + p) mod l is computed in 64 bits: the memo's 32-bit sum wraps
/// for large p and can then map two indices to one value.
constexpr std::uint32_t kensler_permute(std::uint32_t i, std::uint32_t l, std::uint32_t p) noexcept {
  const std::uint32_t walked = multi_jittered_detail::kensler_walk(i, l, multi_jittered_detail::walk_mask(l), p);
  return static_cast<std::uint32_t>((static_cast<std::uint64_t>(walked) + p) % l);
}

/// kensler_permute over one domain l prepared once: the walk's mask, and
/// p mod l by a FastDivider, so a permutation takes no hardware division
/// (a sample draws three). Equal to kensler_permute(i, l, p) (tested).
class KenslerDomain {
 public:
  constexpr KenslerDomain() noexcept = default;
  explicit constexpr KenslerDomain(std::uint32_t l) noexcept
      : l_(l), mask_(multi_jittered_detail::walk_mask(l)), divider_(l >= 2 ? l : 2) {}
  constexpr std::uint32_t size() const noexcept { return l_; }
  constexpr std::uint32_t permute(std::uint32_t i, std::uint32_t p) const noexcept {
    return permute(i, p, rotation(p));
  }
  /// p mod l, the final rotation of permutation p (once per p: permute's third argument).
  constexpr std::uint32_t rotation(std::uint32_t p) const noexcept {
    return l_ < 2 ? 0 : static_cast<std::uint32_t>(p - divider_.quotient(p) * l_);
  }
  constexpr std::uint32_t permute(std::uint32_t i, std::uint32_t p, std::uint32_t rotation) const noexcept {
    if (l_ == 1) return 0;
    const std::uint64_t rotated = std::uint64_t{multi_jittered_detail::kensler_walk(i, l_, mask_, p)} + rotation;
    return static_cast<std::uint32_t>(rotated >= l_ ? rotated - l_ : rotated);  // walked + (p mod l) < 2l
  }

 private:
  std::uint32_t l_ = 1;
  std::uint32_t mask_ = 0;
  FastDivider divider_{};
};

/// Kensler's (2013) hash of (i, p) to 32 bits (his randfloat before scaling).
constexpr std::uint32_t kensler_hash(std::uint32_t i, std::uint32_t p) noexcept {
  i ^= p;
  i ^= i >> 17;
  i ^= i >> 10;
  i *= 0xb36534e5u;
  i ^= i >> 12;
  i ^= i >> 21;
  i *= 0x93fc4795u;
  i ^= 0xdf6e307fu;
  i ^= i >> 17;
  i *= 1u | p >> 18;
  return i;
}

/// Chiu–Shirley–Wang multi-jittered points: `columns` × `rows` strata.
class MultiJittered {
 public:
  MultiJittered(std::uint64_t columns, std::uint64_t rows, std::uint64_t seed)
      : columns_(columns), rows_(rows), seed_(seed) {
    // The value's text is built only on failure: a renderer makes a set per pixel and dimension.
    if (!(columns >= 1 && rows >= 1 && columns <= (std::uint64_t{1} << 52) / rows))
      throw invalid_argument("strata", std::to_string(columns) + "x" + std::to_string(rows),
                             "multi-jittered needs at least one column and row and at most 2^52 points");
  }

  /// The m × k factorization of n with m ≤ k and m as close to √n as
  /// possible (m = 1 when n is prime).
  static MultiJittered closest_to_square(std::uint64_t n, std::uint64_t seed) {
    require(n >= 1 && n <= (std::uint64_t{1} << 52), "n", n, "multi-jittered needs 1 <= n <= 2^52");
    std::uint64_t m = integer_root(n, 2);
    while (n % m != 0) --m;
    return MultiJittered(m, n / m, seed);
  }

  std::uint64_t columns() const noexcept { return columns_; }
  std::uint64_t rows() const noexcept { return rows_; }
  std::uint64_t count() const noexcept { return columns_ * rows_; }
  /// Integers of scratch that fill_x / fill_y / generate need.
  std::uint64_t scratch_size() const noexcept { return std::max(columns_, rows_); }

  /// Point (i, j), the one in stratum column i and row j, has index j·m + i.
  /// Writes the x coordinates of coarse column i into out (row-major n × 2).
  template <class Real = double, class Index>
  void fill_x(std::uint64_t column, Real* out, Index* scratch) const noexcept {
    const std::uint64_t key = jitter_key();
    column_cells(column, scratch, [&](std::uint64_t index, std::uint64_t cell) {
      out[2 * index] = jittered_cell<Real>(cell, key, index, 0, count());
    });
  }
  /// Writes the y coordinates of coarse row j into out.
  template <class Real = double, class Index>
  void fill_y(std::uint64_t row, Real* out, Index* scratch) const noexcept {
    const std::uint64_t key = jitter_key();
    row_cells(row, scratch, [&](std::uint64_t index, std::uint64_t cell) {
      out[2 * index + 1] = jittered_cell<Real>(cell, key, index, 1, count());
    });
  }
  /// All count() points, row-major (x, y), with scratch_size() integers of scratch.
  template <class Real = double, class Index>
  void generate(Real* out, Index* scratch) const noexcept {
    for (std::uint64_t i = 0; i < columns_; ++i) fill_x(i, out, scratch);
    for (std::uint64_t j = 0; j < rows_; ++j) fill_y(j, out, scratch);
  }

  /// visit(index, cell) for the points of coarse column i: their fine
  /// columns (the x intervals of n), after shuffling them in the column
  /// with rows() integers of scratch.
  template <class Index, class Visit>
  void column_cells(std::uint64_t column, Index* scratch, Visit visit) const noexcept {
    random_permutation(scratch, rows_, hash64(seed_, 0x4d4a58ULL, column));
    for (std::uint64_t j = 0; j < rows_; ++j) visit(j * columns_ + column, column * rows_ + scratch[j]);
  }
  /// visit(index, cell) for the points of coarse row j: their fine rows.
  template <class Index, class Visit>
  void row_cells(std::uint64_t row, Index* scratch, Visit visit) const noexcept {
    random_permutation(scratch, columns_, hash64(seed_, 0x4d4a59ULL, row));
    for (std::uint64_t i = 0; i < columns_; ++i) visit(row * columns_ + i, row * columns_ + scratch[i]);
  }
  /// The jitter chain (strata.hpp) of the set: point `index` in fine interval
  /// `cell` of coordinate dim is jittered_cell(cell, jitter_key(), index, dim, count()).
  std::uint64_t jitter_key() const noexcept { return jitter_chain(seed_, 0x4d4a4a4954ULL); }

 private:
  std::uint64_t columns_;
  std::uint64_t rows_;
  std::uint64_t seed_;
};

/// Kensler's correlated multi-jittered points, index-addressable.
class CorrelatedMultiJittered {
 public:
  /// n points (1 ≤ n < 2^32), aspect ratio a = columns / rows > 0. The
  /// 64-bit seed is hashed to Kensler's 32-bit pattern number p.
  CorrelatedMultiJittered(std::uint64_t count, std::uint64_t seed, double aspect = 1.0)
      : count_(count), pattern_(pattern_of(seed)) {
    require(count >= 1 && count <= 0xffffffffULL, "n", count,
            "correlated multi-jittered takes 1 <= n <= 2^32 - 1 (32-bit hash permutations)");
    require(std::isfinite(aspect) && aspect > 0, "aspect", aspect, "must be a positive number");
    // m = ⌊√(n a)⌋, exact for a = 1 (the memo's sqrtf rounds for large n).
    std::uint64_t m = aspect == 1.0
                          ? integer_root(count, 2)
                          : static_cast<std::uint64_t>(std::floor(std::sqrt(static_cast<double>(count) * aspect)));
    columns_ = std::clamp<std::uint64_t>(m, 1, count);
    rows_ = (count + columns_ - 1) / columns_;
    all_ = KenslerDomain(static_cast<std::uint32_t>(count_));
    across_ = KenslerDomain(static_cast<std::uint32_t>(columns_));
    down_ = KenslerDomain(static_cast<std::uint32_t>(rows_));
    column_divider_ = FastDivider(columns_ >= 2 ? columns_ : 2);
  }

  /// Kensler's p of a seed (the constructor's pattern()).
  static std::uint32_t pattern_of(std::uint64_t seed) noexcept {
    return static_cast<std::uint32_t>(hash64(seed, 0x434d4aULL) >> 32);
  }

  std::uint64_t count() const noexcept { return count_; }
  std::uint64_t columns() const noexcept { return columns_; }
  std::uint64_t rows() const noexcept { return rows_; }
  /// Kensler's p.
  std::uint32_t pattern() const noexcept { return pattern_; }
  /// Whether n = columns × rows, so the set is Latin in x and stratified in
  /// columns × rows cells as well as Latin in y.
  bool complete() const noexcept { return columns_ * rows_ == count_; }

  /// What a point of pattern p needs of p: the five derived patterns of
  /// Kensler's listing and the three permutations' rotations, derived once
  /// per pattern (keys(p)), not per point.
  struct Keys {
    std::uint32_t shuffle, across, down, jitter_x, jitter_y;
    std::uint32_t shuffle_rotation, across_rotation, down_rotation;
  };
  Keys keys(std::uint32_t p) const noexcept {
    const std::uint32_t shuffle = p * 0x51633e2du, across = p * 0x68bc21ebu, down = p * 0x02e5be93u;
    return {shuffle,
            across,
            down,
            p * 0x967a889bu,
            p * 0x368cc8b7u,
            all_.rotation(shuffle),
            across_.rotation(across),
            down_.rotation(down)};
  }

  template <class Real = double>
  Real sample(std::uint64_t index, unsigned dim) const noexcept {
    const Keys k = keys(pattern_);
    const std::uint32_t s = shuffled(k, index);
    return dim == 0 ? x_of<Real>(k, s) : y_of<Real>(k, s);
  }
  /// Coordinates 0 … coordinates − 1 (at most 2) of point `index` of the
  /// set of pattern p, from keys(p) (pattern_of(seed): the same count,
  /// aspect and seed give sample's points), the shuffled index shared by both.
  template <class Real = double>
  void sample_for(const Keys& keys, std::uint64_t index, unsigned coordinates, Real* out) const noexcept {
    if (coordinates == 0) return;
    const std::uint32_t s = shuffled(keys, index);
    out[0] = x_of<Real>(keys, s);
    if (coordinates >= 2) out[1] = y_of<Real>(keys, s);
  }
  /// sample_for of the point whose shuffled index is s (shuffled(keys,
  /// index)), the column and row permutations read from tables
  /// (columns[c] = permuted_column(keys, c), rows[r] = permuted_row(keys, r)):
  /// a set of n points takes m + k permutations of its columns and rows
  /// instead of two per point (the same points).
  template <class Real = double, class Entry>
  void sample_of_shuffled(const Keys& keys, const Entry* columns, const Entry* rows, std::uint32_t s,
                          unsigned coordinates, Real* out) const noexcept {
    if (coordinates == 0) return;
    const std::uint32_t row = row_of(s);
    out[0] = x_at<Real>(keys, s, columns[s - row * columns_], rows[row]);
    if (coordinates >= 2) out[1] = y_of<Real>(keys, s);
  }
  /// Column c's place among the columns (Kensler's sx of the points in it).
  std::uint32_t permuted_column(const Keys& k, std::uint32_t c) const noexcept {
    return across_.permute(c, k.across, k.across_rotation);
  }
  /// Row r's place within its column's cell (Kensler's sy of the points in it).
  std::uint32_t permuted_row(const Keys& k, std::uint32_t r) const noexcept {
    return down_.permute(r, k.down, k.down_rotation);
  }
  /// Kensler's shuffled sample index s of point `index` (a permutation of 0 … n − 1).
  std::uint32_t shuffled(const Keys& k, std::uint64_t index) const noexcept {
    return all_.permute(static_cast<std::uint32_t>(index), k.shuffle, k.shuffle_rotation);
  }

 private:
  std::uint32_t row_of(std::uint32_t s) const noexcept {  // s / m
    return columns_ >= 2 ? static_cast<std::uint32_t>(column_divider_.quotient(s)) : s;
  }
  template <class Real>
  Real x_of(const Keys& k, std::uint32_t s) const noexcept {
    const std::uint32_t row = row_of(s);
    return x_at<Real>(k, s, permuted_column(k, static_cast<std::uint32_t>(s - row * columns_)), permuted_row(k, row));
  }
  template <class Real>
  Real x_at(const Keys& k, std::uint32_t s, std::uint64_t sx, std::uint64_t sy) const noexcept {
    const double jx = kensler_hash(s, k.jitter_x) * 0x1.0p-32;
    // (sx + (sy + jx) / k) / m = (sx·k + sy + jx) / (m·k)
    return cell_coordinate<Real>(sx * rows_ + sy, jx, columns_ * rows_);
  }
  template <class Real>
  Real y_of(const Keys& k, std::uint32_t s) const noexcept {
    const double jy = kensler_hash(s, k.jitter_y) * 0x1.0p-32;
    return cell_coordinate<Real>(s, jy, count_);
  }

  std::uint64_t count_;
  std::uint32_t pattern_;
  std::uint64_t columns_ = 1;
  std::uint64_t rows_ = 1;
  KenslerDomain all_, across_, down_;  ///< the permutations over n, m and k
  FastDivider column_divider_;         ///< s / m (m ≥ 2)
};

}  // namespace stratum
