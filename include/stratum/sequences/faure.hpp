#pragma once
/// Faure's (0, s)-sequence (Faure 1982, "Discrépance de suites associées à
/// un système de numération (en dimension s)"): a digital sequence in the
/// prime base b = the smallest prime ≥ s, whose generator matrices are the
/// powers of the Pascal matrix modulo b,
///   C_j = P^j,  (P^j)[r][c] = binom(c, r) · j^(c−r) mod b  (r ≤ c, 0 else),
/// so coordinate j of point i has the digits y = C_j · a (mod b) of the
/// index's base-b digits a, read as 0.y_0 y_1 … (C_0 = I: the van der Corput
/// sequence in base b). Every block of b^m consecutive points starting at a
/// multiple of b^m is a (0, m, s)-net in base b: each elementary interval
/// Π [a_j b^-k_j, (a_j + 1) b^-k_j) with Σ k_j = m holds exactly one point
/// (Niederreiter 1992, "Random Number Generation and Quasi-Monte Carlo
/// Methods", Sec. 4.2), the best t a sequence can have.
///
/// The digit word. digit_word(i, j) is the integer Σ y_r b^r, so the point is
/// the radical inverse φ_b(digit_word): any randomizer of radical inverses
/// in base b (include/stratum/randomizers/: permute, owen, xor) applied to
/// the digit word randomizes the point's digits, and each keeps the net
/// property (it maps elementary intervals onto elementary intervals of the
/// same shape). Output digits are kept at positions r < R(b), R the largest
/// with b^R ≤ 2^64, so the word fits 64 bits; digit R and beyond are nonzero
/// only for indices ≥ b^R (≥ 2^64 / b) and weigh less than b^-R < b·2^-64,
/// below double resolution for b < 2^11.
#include <cstdint>
#include <string>
#include <vector>

#include "stratum/randomizers/digits.hpp"
#include "stratum/sequences/radical_inverse.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/real.hpp"

namespace stratum {

class Faure {
 public:
  /// Largest s: base 1031, where a net of b^2 points already has 10^6.
  static constexpr unsigned max_dimensions = 1024;

  explicit Faure(unsigned dimensions) : dimensions_(dimensions) {
    require(dimensions >= 1 && dimensions <= max_dimensions, "d", dimensions,
            "Faure supports 1 to " + std::to_string(max_dimensions) + " dimensions");
    base_ = base_for(dimensions);
    reciprocal_ = radical_inverse_reciprocal(base_);
    divider_ = FastDivider(base_);
    index_digits_ = 0;
    for (unsigned __int128 power = 1; power < (static_cast<unsigned __int128>(1) << 64); power *= base_)
      ++index_digits_;
    output_digits_ = 0;
    for (unsigned __int128 power = base_; power <= (static_cast<unsigned __int128>(1) << 64); power *= base_)
      ++output_digits_;
    build_matrices();
  }

  unsigned dimensions() const noexcept { return dimensions_; }
  std::uint32_t base() const noexcept { return base_; }
  /// Digits of a 64-bit index (the smallest K with b^K ≥ 2^64).
  unsigned index_digits() const noexcept { return index_digits_; }
  /// Output digit positions kept, R(b): the largest R with b^R ≤ 2^64.
  unsigned output_digits() const noexcept { return output_digits_; }

  /// The smallest prime ≥ max(s, 2): Faure's base for s dimensions.
  static constexpr std::uint32_t base_for(unsigned s) noexcept {
    for (std::uint32_t b = s < 2 ? 2 : s;; ++b) {
      bool prime = true;
      for (std::uint32_t f = 2; f * f <= b; ++f)
        if (b % f == 0) prime = false;
      if (prime) return b;
    }
  }

  /// C_dim[row][col] = binom(col, row) · dim^(col − row) mod b.
  std::uint32_t generator(unsigned dim, unsigned row, unsigned col) const noexcept {
    return matrices_[(static_cast<std::size_t>(dim) * output_digits_ + row) * index_digits_ + col];
  }

  /// Σ_r y_r b^r with y = C_dim · (digits of index) mod b, r < R(b).
  std::uint64_t digit_word(std::uint64_t index, unsigned dim) const noexcept {
    // Base 2 at a renderer's indices inline (C_0 = I, all 64 digits kept; a table below 256), the rest out of line.
    if (base_ == 2 && (dim == 0 || index < 256)) return dim == 0 ? index : low_words2_[std::size_t{dim} * 256 + index];
    return digit_word_general(index, dim);
  }

  template <class Real = double>
  Real sample(std::uint64_t index, unsigned dim) const noexcept {
    return to_unit<Real>(radical_inverse(base_, digit_word(index, dim), reciprocal_));
  }

 private:
  [[gnu::noinline]] std::uint64_t digit_word_general(std::uint64_t index, unsigned dim) const noexcept {
    if (base_ == 2) {  // y = C·a over GF(2): the columns of the index's 1 bits, xor-ed (as Sobol's)
      const std::uint64_t* columns = columns2_.data() + std::size_t{dim} * 64;
      std::uint64_t word = 0;
      for (; index != 0; index &= index - 1) word ^= columns[countr_zero64(index)];
      return word;
    }
    // Quotients by b by multiplication (exact below 2^(64 − ⌈log2 b⌉): the
    // row sums always, an index mostly; a hardware division above).
    std::uint32_t digits[64];
    unsigned count = 0;
    for (; index != 0; ++count) {
      const std::uint64_t next = divider_.quotient(index);
      digits[count] = static_cast<std::uint32_t>(index - next * base_);
      index = next;
    }
    const std::uint32_t* matrix = matrices_.data() + static_cast<std::size_t>(dim) * output_digits_ * index_digits_;
    std::uint64_t word = 0;
    for (unsigned r = count < output_digits_ ? count : output_digits_; r-- > 0;) {
      const std::uint32_t* row = matrix + static_cast<std::size_t>(r) * index_digits_;
      std::uint64_t sum = 0;  // ≤ 64 terms below b² ≤ 2^21 each: < 2^27, in the divider's exact range
      for (unsigned c = r; c < count; ++c) sum += static_cast<std::uint64_t>(row[c]) * digits[c];
      word = word * base_ + (sum - divider_.quotient(sum) * base_);
    }
    return word;
  }

  // C_j = P^j for j < s, from Pascal's triangle mod b and powers of j mod b.
  void build_matrices() {
    const unsigned rows = output_digits_, cols = index_digits_;
    std::vector<std::uint32_t> binomial(static_cast<std::size_t>(cols) * cols, 0);  // [c][r]
    for (unsigned c = 0; c < cols; ++c) {
      binomial[c * cols] = 1;
      for (unsigned r = 1; r <= c; ++r)
        binomial[c * cols + r] = (binomial[(c - 1) * cols + r - 1] + binomial[(c - 1) * cols + r]) % base_;
    }
    matrices_.assign(static_cast<std::size_t>(dimensions_) * rows * cols, 0);
    std::vector<std::uint32_t> powers(cols);
    for (unsigned j = 0; j < dimensions_; ++j) {
      powers[0] = 1;
      for (unsigned e = 1; e < cols; ++e)
        powers[e] = static_cast<std::uint32_t>(std::uint64_t{powers[e - 1]} * j % base_);
      for (unsigned r = 0; r < rows; ++r)
        for (unsigned c = r; c < cols; ++c)
          matrices_[(static_cast<std::size_t>(j) * rows + r) * cols + c] =
              static_cast<std::uint32_t>(std::uint64_t{binomial[c * cols + r]} * powers[c - r] % base_);
    }
    if (base_ != 2) return;
    columns2_.assign(static_cast<std::size_t>(dimensions_) * 64, 0);  // R = K = 64
    for (unsigned j = 0; j < dimensions_; ++j)
      for (unsigned c = 0; c < 64; ++c)
        for (unsigned r = 0; r <= c; ++r) columns2_[std::size_t{j} * 64 + c] |= std::uint64_t{generator(j, r, c)} << r;
    low_words2_.assign(static_cast<std::size_t>(dimensions_) * 256, 0);
    for (unsigned j = 0; j < dimensions_; ++j)
      for (unsigned i = 1; i < 256; ++i)  // word(i) = word(i without its lowest bit) ⊕ that bit's column
        low_words2_[std::size_t{j} * 256 + i] =
            low_words2_[std::size_t{j} * 256 + (i & (i - 1))] ^ columns2_[std::size_t{j} * 64 + countr_zero64(i)];
  }

  unsigned dimensions_;
  std::uint32_t base_ = 2;
  std::uint64_t reciprocal_ = 0;
  FastDivider divider_;
  unsigned index_digits_ = 0;
  unsigned output_digits_ = 0;
  std::vector<std::uint32_t> matrices_;    // dimensions × R × K, row-major per dimension
  std::vector<std::uint64_t> columns2_;    // base 2: each column as a word (bit r: row r), dimensions × 64
  std::vector<std::uint64_t> low_words2_;  // base 2: the digit words of indices < 256, dimensions × 256
};

}  // namespace stratum
