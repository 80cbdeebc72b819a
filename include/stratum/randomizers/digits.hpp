#pragma once
/// Base-b digit machinery shared by the randomizers of radical-inverse
/// sequences (Halton 1960, Hammersley 1964): a scrambled radical inverse
/// writes the digits a_j of an index in base b as 0.π_0(a_0) π_1(a_1) …
/// with one permutation π_j of {0..b−1} per digit position (Owen 2017, "A
/// randomized Halton algorithm in R"; scipy.stats.qmc.Halton(scramble=True)).
///
/// Digits kept. Every position j < K(b) is scrambled, K(b) the smallest K
/// with b^K ≥ 2^64: 64 digits in base 2, 41 in base 3, 28 in base 5, 23 in
/// base 7, 19 in base 11, 18 in base 13, 16 in bases 17 and 19, 15 in base
/// 23, 14 in base 29, 7 in base 1021, 5 in bases 7919 and 8161. The index's
/// own digits are all there (an index < 2^64 has ≤ K digits) and, past its
/// last digit, the digit 0 of every further position is permuted too (its
/// permutation is no identity), so a point is random down to 2^-64, below
/// the output's resolution 2^-53 (digits beyond K weigh less than 2^-64).
/// scipy permutes ⌈54 / log2 b⌉ − 1 positions (53 in base 2, 34 in base 3).
///
/// Arithmetic. The value is a 64-bit binary fraction: each digit adds
/// π_j(a_j)·W_j with W_j = ⌊2^128 / b^(j+1)⌋ in 128 bits, digits are added in
/// fixed groups ("chunks") of m(b) positions and each chunk's sum is
/// truncated to 64 bits; the 53 leading bits make the double. The chunks
/// depend on the base only, so a chunk's value can come from a table or be
/// computed on the spot with bit-identical results.
///
/// Speed. PositionalDigitScrambler tabulates, at construction, the value of
/// every chunk (b^m ≤ 4096 entries), so a sample is one table load per
/// chunk of the index's digits plus a precomputed constant for all the
/// positions past its last digit. Quotients by b^m use multiply-by-reciprocal (Lemire,
/// Kaser, Kurz 2019, "Faster remainder by direct computation"), exact for
/// indices below 2^(64 − ⌈log2 b^m⌉), with a hardware division above.
/// fill() writes a run of consecutive indices as one table load and one add
/// per value. Tables cover the indices up to the max_index given at
/// construction; larger indices take a slow path with the same results.
///
/// Device code (docs/gpu.md): a sample reads the tables through a View
/// (pointers and the rule, trivially copyable), taken by a kernel by value:
/// view() points into the scrambler, view(copy) into copies that `copy`
/// makes of each array (e.g. in device memory).
#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "stratum/util/bits.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/fast_divider.hpp"
#include "stratum/util/host_device.hpp"
#include "stratum/util/real.hpp"

namespace stratum {

namespace digits_detail {

using u128 = unsigned __int128;

/// Largest base the digit randomizers take (a permutation per position is a
/// table of b entries).
inline constexpr std::uint32_t max_base = 65536;
/// Largest chunk table: b^m ≤ 4096 entries (32 KiB).
inline constexpr std::uint32_t max_chunk_size = 4096;

/// K(b) by powers of b in 64 bits.
constexpr unsigned digit_count_by_powers(std::uint32_t base) noexcept {
  if ((base & (base - 1)) == 0) {  // b = 2^k: ⌈64 / k⌉
    const auto k = static_cast<unsigned>(std::countr_zero(base));
    return (64 + k - 1) / k;
  }
  unsigned count = 1;  // b^count ≤ 2^64 − 1 < b^K, and b^K ≠ 2^64 for such b
  for (std::uint64_t power = base; power <= ~std::uint64_t{0} / base; power *= base) ++count;
  return count + 1;
}

/// K(b) of the bases below 256, tabulated at compile time.
inline constexpr std::array<std::uint8_t, 256> small_digit_counts = [] {
  std::array<std::uint8_t, 256> counts{};
  for (std::uint32_t b = 2; b < counts.size(); ++b) counts[b] = static_cast<std::uint8_t>(digit_count_by_powers(b));
  return counts;
}();

/// K(b): the smallest K with b^K ≥ 2^64, the number of positions scrambled
/// (a scrambler bound per pixel set computes it: a loop of up to 41 steps
/// was a large part of its construction in base 3).
constexpr unsigned digit_count(std::uint32_t base) noexcept {
  return base < small_digit_counts.size() ? small_digit_counts[base] : digit_count_by_powers(base);
}

/// The largest m ≥ 1 with b^m ≤ bound (bound ≤ 2^32: no overflow).
constexpr unsigned digits_within(std::uint32_t base, std::uint64_t bound) noexcept {
  unsigned m = 1;
  for (std::uint64_t size = base; size * base <= bound; size *= base) ++m;
  return m;
}

/// m(b): positions per chunk, the largest m ≥ 1 with b^m ≤ 4096.
constexpr unsigned chunk_digits(std::uint32_t base) noexcept { return digits_within(base, max_chunk_size); }

/// W_j = ⌊2^128 / b^(j+1)⌋, the 128-bit weight of position j.
constexpr u128 digit_weight(std::uint32_t base, unsigned position) noexcept {
  u128 power = 1;
  for (unsigned j = 0; j <= position; ++j) power *= base;
  const u128 all_ones = ~u128{0};  // 2^128 − 1
  return all_ones / power + (all_ones % power == power - 1 ? 1 : 0);
}

/// W_j for every position j < K(b), computed once per process and kept for
/// its lifetime, shared by every thread (each is a 128-bit division, which
/// made up most of a scrambler's construction when a renderer builds one per
/// pixel set): a scrambler points at them or copies them.
inline const u128* shared_digit_weights(std::uint32_t base) {
  static std::array<std::atomic<const u128*>, max_base + 1> tables{};  // zero-initialized, no static constructor
  std::atomic<const u128*>& slot = tables[base];
  if (const u128* table = slot.load(std::memory_order_acquire)) return table;
  auto fresh = std::make_unique<u128[]>(digit_count(base));
  for (unsigned j = 0; j < digit_count(base); ++j) fresh[j] = digit_weight(base, j);
  const u128* expected = nullptr;
  if (slot.compare_exchange_strong(expected, fresh.get(), std::memory_order_acq_rel)) return fresh.release();
  return expected;  // another thread's, equal
}

/// A 64-bit binary fraction as a double in [0, 1): its 53 leading bits.
STRATUM_HOST_DEVICE constexpr double fraction_to_double(std::uint64_t fraction) noexcept {
  return static_cast<double>(static_cast<std::int64_t>(fraction >> 11)) * 0x1.0p-53;
}

/// Validates the bases of a digit randomizer (one per dimension).
inline void require_digit_bases(const std::vector<std::uint32_t>& bases) {
  require(!bases.empty(), "d", 0, "a digit randomizer needs at least one dimension");
  for (std::uint32_t base : bases)
    if (base < 2 || base > max_base)  // the message built only when needed: scramblers are bound per pixel set
      throw invalid_argument("base", std::to_string(base),
                             "digit randomizers take bases in [2, " + std::to_string(max_base) + "]");
}

/// A randomizer that applies one permutation π_j of {0..b−1} per (dimension,
/// position) to the index's digits, tabulated as described above. `Rule`
/// supplies the permutations:
///   std::uint32_t image(unsigned dim, unsigned position, std::uint32_t base, std::uint32_t digit) const;
///   void permutation(unsigned dim, unsigned position, std::uint32_t base, std::uint32_t* images) const;
/// (π_j(digit), and all b images at once for the tables).
template <class Rule>
class PositionalDigitScrambler {
 private:
  struct Dimension {
    std::uint32_t base;
    unsigned positions;         // K(b)
    unsigned digits_per_chunk;  // m(b)
    unsigned chunk_count;       // ⌈K / m⌉
    std::size_t first_chunk;    // into chunks_ (chunk_count + 1 entries, the last a sentinel)
    std::size_t first_weight;   // into weights_ (K entries)
    FastDivider divider;        // by b^m
  };
  struct Chunk {
    std::size_t offset;       // into tables_
    std::uint64_t size;       // tabulated entries (0: none)
    std::uint64_t zero_tail;  // Σ of the values of digits 0 in this and every later chunk
  };

 public:
  /// The per-sample path: the rule and the scrambler's arrays by pointer.
  class View {
   public:
    STRATUM_HOST_DEVICE View(Rule rule, const Dimension* dims, const Chunk* chunks, const u128* weights,
                             const std::uint64_t* tables) noexcept
        : rule_(rule), dims_(dims), chunks_(chunks), weights_(weights), tables_(tables) {}

    /// See PositionalDigitScrambler::fraction.
    STRATUM_HOST_DEVICE std::uint64_t fraction(std::uint64_t index, unsigned dim) const noexcept {
      return chunks_from(index, dim, dims_[dim], 0);
    }
    template <class Real = double>
    STRATUM_HOST_DEVICE Real sample(std::uint64_t index, unsigned dim) const noexcept {
      return to_unit<Real>(fraction_to_double(fraction(index, dim)));
    }

    /// See PositionalDigitScrambler::chunk_value.
    STRATUM_HOST_DEVICE std::uint64_t chunk_value(unsigned dim, unsigned chunk, std::uint64_t value) const noexcept {
      const Dimension& d = dims_[dim];
      u128 sum = 0;
      for (unsigned t = 0; t < d.digits_per_chunk; ++t) {
        const unsigned position = chunk * d.digits_per_chunk + t;
        if (position >= d.positions) break;
        const auto digit = static_cast<std::uint32_t>(value % d.base);
        value /= d.base;
        sum += static_cast<u128>(rule_.image(dim, position, d.base, digit)) * weights_[d.first_weight + position];
      }
      return static_cast<std::uint64_t>(sum >> 64);
    }

    // Σ over chunks c ≥ first_chunk of the chunk values of `index`, whose
    // digit group 0 is chunk `first_chunk`.
    STRATUM_HOST_DEVICE std::uint64_t chunks_from(std::uint64_t index, unsigned dim, const Dimension& d,
                                                  unsigned first_chunk) const noexcept {
      const Chunk* chunk = chunks_ + d.first_chunk;
      std::uint64_t sum = 0;
      unsigned c = first_chunk;
      while (index != 0) {
        const std::uint64_t next = d.divider.quotient(index);
        const std::uint64_t r = index - next * d.divider.divisor();
        sum += r < chunk[c].size ? tables_[chunk[c].offset + r] : chunk_value(dim, c, r);
        index = next;
        ++c;
      }
      return sum + chunk[c].zero_tail;
    }

   private:
    Rule rule_;
    const Dimension* dims_;
    const Chunk* chunks_;
    const u128* weights_;
    const std::uint64_t* tables_;
  };

  /// Tables cover the indices 0..max_index (larger ones are exact but slow).
  PositionalDigitScrambler(Rule rule, std::vector<std::uint32_t> bases, std::uint64_t max_index)
      : rule_(std::move(rule)), max_index_(max_index) {
    require_digit_bases(bases);
    dims_.reserve(bases.size());
    for (unsigned dim = 0; dim < bases.size(); ++dim) add_dimension(dim, bases[dim]);
  }

  unsigned dimensions() const noexcept { return static_cast<unsigned>(dims_.size()); }
  std::uint32_t base(unsigned dim) const noexcept { return dims_[dim].base; }
  std::uint64_t max_index() const noexcept { return max_index_; }
  const Rule& rule() const noexcept { return rule_; }
  /// Number of 64-bit table entries held (memory: 8 bytes each).
  std::size_t table_entries() const noexcept { return tables_.size(); }

  /// The per-sample path reading this object's arrays.
  View view() const noexcept { return View(rule_, dims_.data(), chunks_.data(), weights_.data(), tables_.data()); }
  /// The per-sample path reading copies of the arrays: copy(data, count)
  /// copies `count` elements (trivially copyable) and returns the copy's address.
  template <class Copy>
  View view(Copy&& copy) const {
    return View(rule_, copy(dims_.data(), dims_.size()), copy(chunks_.data(), chunks_.size()),
                copy(weights_.data(), weights_.size()), copy(tables_.data(), tables_.size()));
  }

  /// The scrambled radical inverse of `index` in dimension `dim` as a 64-bit
  /// binary fraction.
  std::uint64_t fraction(std::uint64_t index, unsigned dim) const noexcept { return view().fraction(index, dim); }

  /// The scrambled radical inverse as a double or float in [0, 1).
  template <class Real = double>
  Real sample(std::uint64_t index, unsigned dim) const noexcept {
    return view().template sample<Real>(index, dim);
  }

  /// out[k·stride] = sample(first + k, dim) for k < count: one table load and
  /// one add per value along runs of consecutive indices.
  void fill(std::uint64_t first, std::size_t count, unsigned dim, double* out, std::size_t stride) const noexcept {
    if (count == 0) return;
    const Dimension& d = dims_[dim];
    const Chunk& low = chunks_[d.first_chunk];
    const std::uint64_t size = d.divider.divisor();
    if (low.size != size || count - 1 > max_index_ || first > max_index_ - (count - 1)) {
      for (std::size_t k = 0; k < count; ++k) out[k * stride] = sample(first + k, dim);
      return;
    }
    const std::uint64_t* table = tables_.data() + low.offset;
    const View v = view();
    std::uint64_t high = d.divider.quotient(first);
    std::uint64_t r = first - high * size;
    while (count != 0) {
      const std::uint64_t above = v.chunks_from(high, dim, d, 1);
      const std::size_t run = static_cast<std::size_t>(std::min<std::uint64_t>(size - r, count));
      const std::uint64_t* row = table + r;
      for (std::size_t k = 0; k < run; ++k) out[k * stride] = fraction_to_double(row[k] + above);
      out += run * stride;
      count -= run;
      r = 0;
      ++high;
    }
  }

  /// Value of chunk `chunk` of dimension `dim` for chunk digits `value`,
  /// computed from the permutations (the tables hold the same numbers).
  std::uint64_t chunk_value(unsigned dim, unsigned chunk, std::uint64_t value) const noexcept {
    return view().chunk_value(dim, chunk, value);
  }

 private:
  void add_dimension(unsigned dim, std::uint32_t base) {
    Dimension d{};
    d.base = base;
    d.positions = digit_count(base);
    d.digits_per_chunk = chunk_digits(base);
    d.chunk_count = (d.positions + d.digits_per_chunk - 1) / d.digits_per_chunk;
    d.first_chunk = chunks_.size();
    d.first_weight = weights_.size();
    std::uint64_t size = 1;
    for (unsigned t = 0; t < d.digits_per_chunk; ++t) size *= base;
    d.divider = FastDivider(size);
    const u128* weights = shared_digit_weights(base);
    weights_.insert(weights_.end(), weights, weights + d.positions);
    dims_.push_back(d);

    // Tabulated entries per chunk: all b^m while the index range spans the
    // chunk, the leading values below that, none where max_index's digits
    // are all 0 (only the zero_tail constant is needed there).
    std::vector<std::uint32_t> images(base);
    std::vector<u128> partial;
    std::uint64_t rest = max_index_;
    for (unsigned c = 0; c < d.chunk_count; ++c) {
      const std::uint64_t entries = (c > 0 && rest == 0) ? 0 : rest >= size - 1 ? size : rest + 1;
      rest /= size;
      chunks_.push_back({tables_.size(), entries, 0});
      if (entries == 0) continue;
      // Sums of π_j(a_j)·W_j over the chunk's positions for the digit strings
      // 0..entries−1, built one position at a time (least significant digit
      // first): after t positions, partial[x] for x < min(b^t, entries). Only
      // the rows the table keeps are built (a few when max_index is small).
      partial.assign(1, 0);
      for (unsigned t = 0; t < d.digits_per_chunk; ++t) {
        const unsigned position = c * d.digits_per_chunk + t;
        const std::size_t previous = partial.size();
        const std::size_t next = static_cast<std::size_t>(std::min<std::uint64_t>(previous * base, entries));
        const bool beyond = position >= d.positions;  // digits beyond K add nothing
        if (!beyond) rule_.permutation(dim, position, base, images.data());
        const u128 weight = beyond ? 0 : weights_[d.first_weight + position];
        partial.resize(next);
        // Row a·previous + x = row x plus digit a at this position; rows are
        // written from the top so row x (< previous) is read before its update.
        for (std::size_t a = (next + previous - 1) / previous; a-- > 0;) {
          const std::size_t count = std::min(previous, next - a * previous);
          const u128 add = beyond ? 0 : static_cast<u128>(images[a]) * weight;
          for (std::size_t x = count; x-- > 0;) partial[a * previous + x] = partial[x] + add;
        }
      }
      for (std::uint64_t r = 0; r < entries; ++r) tables_.push_back(static_cast<std::uint64_t>(partial[r] >> 64));
    }
    chunks_.push_back({tables_.size(), 0, 0});  // sentinel: no digits left
    for (unsigned c = d.chunk_count; c-- > 0;) {
      Chunk& chunk = chunks_[d.first_chunk + c];
      const std::uint64_t zero = chunk.size > 0 ? tables_[chunk.offset] : chunk_value(dim, c, 0);
      chunk.zero_tail = zero + chunks_[d.first_chunk + c + 1].zero_tail;
    }
  }

  Rule rule_;
  std::uint64_t max_index_;
  std::vector<Dimension> dims_;
  std::vector<Chunk> chunks_;
  std::vector<u128> weights_;
  std::vector<std::uint64_t> tables_;
};

}  // namespace digits_detail

}  // namespace stratum
