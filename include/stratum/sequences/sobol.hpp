#pragma once
/// Sobol' sequence in base 2 (Sobol' 1967, "On the distribution of points in
/// a cube and the approximate evaluation of integrals") with the direction
/// numbers of Joe and Kuo (2008, "Constructing Sobol sequences with better
/// two-dimensional projections"), new-joe-kuo-6.21201: all 21201 dimensions,
/// generated from scipy's copy by scripts/generate_sobol_table.py, never
/// retyped (stratum/sequences/sobol_directions.hpp); the first 3667 are
/// checked against the table Boost.Random ships.
///
/// Why 64-bit generator matrices: with the usual 32 columns the index wraps
/// at 2^32 and only 32 of a double's 53 bits carry information. Here every
/// dimension has 64 direction numbers v_k = m_k · 2^(64−k), k = 1..64, the
/// Bratley–Fox recursion (Bratley, Fox 1988, "Algorithm 659") being continued
/// past k = 32, so indices up to 2^64 − 1 are distinct points and digital
/// randomizers (stratum/randomizers/base2.hpp) act on all 64 digits. The
/// 64-bit words equal those of boost::random::sobol (a 64-bit engine).
///
/// Point order: Gray-code order by default, x_i = C · (i ⊕ ⌊i/2⌋), which is
/// what scipy.stats.qmc.Sobol(scramble=False).random(n) returns (point 0 is
/// the origin) and what boost::random::sobol returns after skipping the
/// origin (Boost's k-th vector is point k + 1 here). Natural order,
/// x_i = C · i, as in pbrt-v4's SobolSample, is an option. Gray block
/// [m·2^k, (m+1)·2^k) holds the points of natural block gray(m), so every
/// power-of-two prefix [0, 2^k) is the same (t, k, s)-net in both orders.
///
/// Random access: C · digits is two lookups in per-dimension tables of the
/// XORs of columns 0–7 and 8–15 (2 × 256 words), plus one XOR per set digit
/// above bit 15 (a loop over set bits alone mispredicts its exit on almost
/// every call). The same tables exist for the bit-reversed columns, so that
/// hash-based Owen scrambling, which works on reversed words, needs one bit
/// reversal per sample instead of two. Memory: 9 KiB per dimension. Bulk
/// generation should use the Gray-code step x_{i+1} = x_i ⊕ step(i + 1), or
/// aligned blocks, x(m·2^k + r) = x(m·2^k) ⊕ C·digits(r) for r < 2^k (in
/// both orders), which vectorize (src/registry/samplers_sobol.cpp).
///
/// Device code (docs/gpu.md): the per-sample path reads the tables through a
/// Sobol::View, a trivially copyable (dimensions, order, pointer) that a
/// kernel takes by value; view() points into this object, view(copy) into a
/// copy of table() that `copy` makes (e.g. in device memory).
#include <bit>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "stratum/randomizers/base2.hpp"
#include "stratum/sequences/sobol_directions.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"

namespace stratum {

class Sobol {
 public:
  /// Dimensions of the Joe–Kuo table (dimension 0 is van der Corput), as scipy's Sobol.MAXDIM.
  static constexpr unsigned max_dimensions = sobol_joe_kuo::dimensions;
  /// Columns of each generator matrix (bits of the index it can consume).
  static constexpr unsigned columns = 64;

  enum class Order {
    gray,     ///< x_i = C · gray(i): Boost.Random and scipy order
    natural,  ///< x_i = C · i: pbrt-v4 order
  };

 private:
  // Per dimension, twice (plain, then reversed columns): 256 XORs of columns
  // 0–7, 256 XORs of columns 8–15, then the 64 columns.
  static constexpr std::size_t columns_offset = 512;
  static constexpr std::size_t reversed_offset = 512 + columns;
  static constexpr std::size_t block_size = 2 * reversed_offset;

 public:
  /// The per-sample path: the generator's tables by pointer. Cheap to copy;
  /// valid while the table it points into lives.
  class View {
   public:
    STRATUM_HOST_DEVICE constexpr View(unsigned dimensions, Order order, const std::uint64_t* table) noexcept
        : dimensions_(dimensions), order_(order), table_(table) {}
    STRATUM_HOST_DEVICE unsigned dimensions() const noexcept { return dimensions_; }
    STRATUM_HOST_DEVICE Order order() const noexcept { return order_; }
    STRATUM_HOST_DEVICE std::uint64_t digits_of(std::uint64_t index) const noexcept {
      return order_ == Order::gray ? gray_code(index) : index;
    }
    STRATUM_HOST_DEVICE std::uint64_t direction(unsigned dim, unsigned column) const noexcept {
      return table_[std::size_t{dim} * block_size + columns_offset + column];
    }
    STRATUM_HOST_DEVICE std::uint64_t bits(std::uint64_t index, unsigned dim) const noexcept {
      return multiply(digits_of(index), table_ + std::size_t{dim} * block_size);
    }
    STRATUM_HOST_DEVICE std::uint64_t reversed_bits(std::uint64_t index, unsigned dim) const noexcept {
      return multiply(digits_of(index), table_ + std::size_t{dim} * block_size + reversed_offset);
    }
    template <class Real = double>
    STRATUM_HOST_DEVICE Real sample(std::uint64_t index, unsigned dim) const noexcept {
      return bits_to_unit<Real>(bits(index, dim));
    }
    /// See Sobol::sample(index, dim, randomizer).
    template <class Real = double, class Randomizer>
    STRATUM_HOST_DEVICE Real sample(std::uint64_t index, unsigned dim, const Randomizer& randomizer) const noexcept {
      if constexpr (requires { randomizer.dimension(dim).scramble_reversed(std::uint64_t{}); })
        return sample<Real>(index, dim, randomizer.dimension(dim));
      else if constexpr (requires(std::uint64_t w) {
                           { randomizer.scramble_reversed(w) } -> std::same_as<std::uint64_t>;
                         })
        return bits_to_unit<Real>(reverse_bits64(randomizer.scramble_reversed(reversed_bits(index, dim))));
      else if constexpr (requires(std::uint64_t w) {
                           { randomizer(w) } -> std::same_as<std::uint64_t>;
                         })
        return bits_to_unit<Real>(randomizer(bits(index, dim)));
      else {
        static_assert(
            requires(std::uint64_t w) {
              { randomizer(w, dim) } -> std::same_as<std::uint64_t>;
            },
            "a base-2 randomizer maps 64-bit words: r(bits, dim) or r(bits)");
        return bits_to_unit<Real>(randomizer(bits(index, dim), dim));
      }
    }

   private:
    unsigned dimensions_;
    Order order_;
    const std::uint64_t* table_;
  };

  /// The tables of dimensions 0 and 1 (gray order), built once and shared:
  /// the (0,2)-sequence that per-pixel samplers draw from.
  static const Sobol& first_two() {
    static const Sobol sobol(2);
    return sobol;
  }

  explicit Sobol(unsigned dimensions, Order order = Order::gray) : dimensions_(dimensions), order_(order) {
    require(dimensions >= 1 && dimensions <= max_dimensions, "d", dimensions,
            "Sobol supports 1 to 21201 dimensions (the Joe-Kuo table new-joe-kuo-6.21201)");
    data_.resize(std::size_t{dimensions} * block_size);
    for (unsigned dim = 0; dim < dimensions; ++dim) {
      std::uint64_t* block = &data_[std::size_t{dim} * block_size];
      direction_numbers(dim, block + columns_offset);
      for (unsigned k = 0; k < columns; ++k)
        block[reversed_offset + columns_offset + k] = reverse_bits64(block[columns_offset + k]);
      build_tables(block);
      build_tables(block + reversed_offset);
    }
  }

  unsigned dimensions() const noexcept { return dimensions_; }
  Order order() const noexcept { return order_; }

  /// The tables every sample reads (9 KiB per dimension).
  std::span<const std::uint64_t> table() const noexcept { return data_; }
  /// The per-sample path reading this object's tables.
  View view() const noexcept { return View(dimensions_, order_, data_.data()); }
  /// The per-sample path reading copy(table().data(), table().size()), a
  /// copy of the tables (device memory, for a kernel); copy returns its address.
  template <class Copy>
  View view(Copy&& copy) const {
    return View(dimensions_, order_, copy(data_.data(), data_.size()));
  }

  /// Direction number v_{column+1} of dimension dim: column `column` of the
  /// generator matrix as a 64-bit word (most significant bit = first digit).
  std::uint64_t direction(unsigned dim, unsigned column) const noexcept { return view().direction(dim, column); }

  /// Gray code of i: consecutive codes differ in bit ctz(i + 1).
  STRATUM_HOST_DEVICE static constexpr std::uint64_t gray_code(std::uint64_t i) noexcept { return i ^ (i >> 1); }

  /// Index bits the generator matrix multiplies for point `index` (the Gray
  /// code in Gray order, the index itself in natural order).
  std::uint64_t digits_of(std::uint64_t index) const noexcept { return view().digits_of(index); }

  /// Point `index`, dimension `dim`, as a 64-bit binary fraction (unscrambled).
  std::uint64_t bits(std::uint64_t index, unsigned dim) const noexcept { return view().bits(index, dim); }
  /// bits(index, dim) with its 64 bits reversed (first digit in bit 0).
  std::uint64_t reversed_bits(std::uint64_t index, unsigned dim) const noexcept {
    return view().reversed_bits(index, dim);
  }

  /// The word XORed into every point of dimension dim when going from point
  /// i to point i + 1 = next_index (≥ 1): column ctz(i + 1) in Gray order,
  /// columns 0..ctz(i + 1) in natural order.
  std::uint64_t step(std::uint64_t next_index, unsigned dim) const noexcept {
    const unsigned c = static_cast<unsigned>(countr_zero64(next_index));
    if (order_ == Order::gray) return direction(dim, c);
    std::uint64_t x = 0;
    for (unsigned k = 0; k <= c; ++k) x ^= direction(dim, k);
    return x;
  }

  /// Point index, dimension dim, as a double (top 53 bits) or float (top 24 bits).
  template <class Real = double>
  Real sample(std::uint64_t index, unsigned dim) const noexcept {
    return bits_to_unit<Real>(bits(index, dim));
  }

  /// Point index, dimension dim, after a base-2 digital randomizer: either a
  /// seeded one, r(bits, dim), or one already bound to a dimension, r(bits)
  /// (from r.dimension(dim), as pbrt-v4's FastOwenScrambler(hash(dim, seed))).
  /// Randomizers that work on reversed words use the reversed tables.
  template <class Real = double, class Randomizer>
  Real sample(std::uint64_t index, unsigned dim, const Randomizer& randomizer) const noexcept {
    return view().sample<Real>(index, dim, randomizer);
  }

  /// Top 53 (double) or 24 (float) bits of a 64-bit fraction, exactly, in [0, 1).
  template <class Real>
  STRATUM_HOST_DEVICE static constexpr Real bits_to_unit(std::uint64_t word) noexcept {
    if constexpr (sizeof(Real) == sizeof(float)) return bits_to_float(word);
    else return bits_to_double(word);
  }

  /// Generator-matrix columns of dimension dim from the Joe–Kuo table:
  /// out[k − 1] = m_k · 2^(64−k), k = 1..64. Dimension 0 has m_k = 1
  /// (van der Corput); dimension j ≥ 1 uses its primitive polynomial of
  /// degree s (Boost's polynomial j − 1, scipy's poly[j]), whose bits a_s..a_0 (a_s = a_0 = 1) give the recursion
  /// m_k = m_{k−s} ⊕ ⊕_{i=1..s} a_{s−i} · 2^i · m_{k−i} (Bratley, Fox 1988).
  static void direction_numbers(unsigned dim, std::uint64_t* out) {
    std::uint64_t m[columns + 1] = {};
    if (dim == 0) {
      for (unsigned k = 1; k <= columns; ++k) m[k] = 1;
    } else {
      const sobol_joe_kuo::Directions table = sobol_joe_kuo::directions(dim);
      const std::uint64_t poly = table.polynomial;
      const unsigned degree = table.degree;
      for (unsigned k = 1; k <= degree; ++k) m[k] = table.m[k - 1];
      for (unsigned k = degree + 1; k <= columns; ++k) {
        std::uint64_t value = m[k - degree];
        for (unsigned i = 1; i <= degree; ++i)
          if ((poly >> (degree - i)) & 1) value ^= m[k - i] << i;
        m[k] = value;
      }
    }
    for (unsigned k = 1; k <= columns; ++k) out[k - 1] = m[k] << (columns - k);
  }

 private:
  STRATUM_HOST_DEVICE static std::uint64_t multiply(std::uint64_t digits, const std::uint64_t* block) noexcept {
    std::uint64_t x = block[digits & 0xff] ^ block[256 + ((digits >> 8) & 0xff)];
    const std::uint64_t* column = block + columns_offset;
    for (std::uint64_t rest = digits >> 16 << 16; rest != 0; rest &= rest - 1) x ^= column[countr_zero64(rest)];
    return x;
  }

  static void build_tables(std::uint64_t* block) {
    const std::uint64_t* column = block + columns_offset;
    for (unsigned byte = 0; byte < 2; ++byte) {
      std::uint64_t* part = block + 256 * byte;
      part[0] = 0;
      for (unsigned value = 1; value < 256; ++value)
        part[value] = part[value & (value - 1)] ^ column[8 * byte + static_cast<unsigned>(std::countr_zero(value))];
    }
  }

  unsigned dimensions_;
  Order order_;
  std::vector<std::uint64_t> data_;  // dimension-major blocks of block_size words
};

}  // namespace stratum
