#pragma once
/// Randomizers for base-2 digital sequences (Sobol', the (0,2)-sequence, van
/// der Corput): small functors r(bits, dim) → bits on a 64-bit binary
/// fraction, orthogonal to the sequence as in pbrt-v4's SobolSample(a, dim,
/// randomizer), so adding a randomizer never multiplies sampler classes.
/// Each result depends only on (seed, dim, value). Per-dimension keys are the
/// SplitMix64 stream (Steele, Lea, Flood 2014) started at hash64(seed, tag):
/// different dimensions get decorrelated keys, and different randomizers
/// (tags) with the same seed are unrelated.
///
/// All four act on the digits only, so every elementary interval of the
/// input is mapped onto an elementary interval of the same shape: a
/// (t, m, s)-net stays a (t, m, s)-net, and each point becomes uniform on
/// the 2^-64 grid (unbiased estimates; exactly so for XOR and LMS, and for
/// Owen up to the quality of its hash).
///
/// Speed: a seeded functor derives the dimension's key on every call (one
/// SplitMix64 round); hot loops bind a dimension once with dimension(dim),
/// as pbrt-v4 builds FastOwenScrambler(Hash(dim, seed)), and pass that.
/// HashOwenScrambler, the one meant for random access in renderers, keeps
/// the bound scramblers of its first 16 dimensions (264 bytes), so that
/// r(bits, dim) and r.dimension(dim) cost two loads there.
///  - DigitalShift: XOR with a random word (the base-2 digital shift).
///  - LinearMatrixScramble: random nonsingular lower-triangular binary matrix
///    times the digits plus a digital shift (Matoušek 1998, "On the
///    L2-discrepancy for anchored boxes"; scipy's LMS, Sobol scramble=True).
///  - OwenScrambler: exact nested uniform scrambling (Owen 1995, "Randomly
///    permuted (t,m,s)-nets and (t,s)-sequences"): digit b is flipped by a
///    random bit hashed from (seed, dim, all higher digits), for all 64 digits.
///  - HashOwenScrambler: hash-based Owen scrambling (Burley 2020, "Practical
///    hash-based Owen scrambling"): a Laine–Karras-style hash on the
///    bit-reversed word, with Vegdahl's constants (2021, "Building a better
///    LK hash"; pbrt-v4's FastOwenScrambler). See its comment for the 64-bit
///    extension.
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <utility>

#include "stratum/util/bits.hpp"
#include "stratum/util/hash.hpp"
#include "stratum/util/host_device.hpp"

namespace stratum {

namespace base2_detail {

/// Key of dimension dim: output dim + 1 of the SplitMix64 stream at `base`.
STRATUM_HOST_DEVICE constexpr std::uint64_t dimension_key(std::uint64_t base, unsigned dim) noexcept {
  return mix64(base + (static_cast<std::uint64_t>(dim) + 1) * 0x9e3779b97f4a7c15ULL);
}

/// Random word for (key, counter) from a pre-mixed key (hash64's structure
/// with its first mixing step done once per dimension).
STRATUM_HOST_DEVICE constexpr std::uint64_t keyed_word(std::uint64_t mixed_key, std::uint64_t counter) noexcept {
  return mix64((mixed_key ^ (counter * 0xd1342543de82ef95ULL + 0x632be59bd9b4e019ULL)) + 0x9e3779b97f4a7c15ULL);
}

}  // namespace base2_detail

/// The identity: the unscrambled construction.
struct NoRandomizer {
  STRATUM_HOST_DEVICE constexpr std::uint64_t operator()(std::uint64_t bits, unsigned /*dim*/) const noexcept {
    return bits;
  }
};

/// Digital shift in base 2: x ⊕ s_dim with s_dim uniform on 64-bit words.
class DigitalShift {
 public:
  STRATUM_HOST_DEVICE explicit constexpr DigitalShift(std::uint64_t seed) noexcept
      : base_(hash64(seed, 0x786f72ULL /* "xor" */)) {}

  /// The word XORed into dimension dim.
  STRATUM_HOST_DEVICE constexpr std::uint64_t shift(unsigned dim) const noexcept {
    return base2_detail::dimension_key(base_, dim);
  }

  STRATUM_HOST_DEVICE constexpr std::uint64_t operator()(std::uint64_t bits, unsigned dim) const noexcept {
    return bits ^ shift(dim);
  }

 private:
  std::uint64_t base_;
};

/// Random linear scrambling plus digital shift (Matoušek 1998): y = L·x ⊕ s,
/// with L a nonsingular lower-triangular 64 × 64 binary matrix acting on the
/// digits (first digit = most significant bit). Output digit k is digit k
/// XOR a random combination of digits 1..k−1, so the first m digits of y
/// depend only, and bijectively, on the first m digits of x. In word form,
/// column p of L (the image of bit p) is bit p plus random bits below p.
class LinearMatrixScramble {
 public:
  /// L and s of one dimension; cheap to copy.
  class Dimension {
   public:
    STRATUM_HOST_DEVICE explicit constexpr Dimension(std::uint64_t key) noexcept
        : mixed_(mix64(key + 0x9e3779b97f4a7c15ULL)), shift_(base2_detail::keyed_word(mixed_, 64)) {}

    /// Column p of L: the image of the word with only bit p set.
    STRATUM_HOST_DEVICE constexpr std::uint64_t column(unsigned p) const noexcept {
      const std::uint64_t below = (std::uint64_t{1} << p) - 1;
      return (std::uint64_t{1} << p) | (base2_detail::keyed_word(mixed_, p) & below);
    }
    /// L·x over GF(2), without the shift (linear, so bulk generators can
    /// scramble the direction numbers once instead of every point).
    STRATUM_HOST_DEVICE constexpr std::uint64_t linear(std::uint64_t x) const noexcept {
      std::uint64_t y = 0;
      for (; x != 0; x &= x - 1) y ^= column(static_cast<unsigned>(countr_zero64(x)));
      return y;
    }
    STRATUM_HOST_DEVICE constexpr std::uint64_t shift() const noexcept { return shift_; }
    STRATUM_HOST_DEVICE constexpr std::uint64_t operator()(std::uint64_t bits) const noexcept {
      return linear(bits) ^ shift_;
    }

   private:
    std::uint64_t mixed_;
    std::uint64_t shift_;
  };

  STRATUM_HOST_DEVICE explicit constexpr LinearMatrixScramble(std::uint64_t seed) noexcept
      : base_(hash64(seed, 0x6c6d73ULL /* "lms" */)) {}

  STRATUM_HOST_DEVICE constexpr Dimension dimension(unsigned dim) const noexcept {
    return Dimension(base2_detail::dimension_key(base_, dim));
  }
  STRATUM_HOST_DEVICE constexpr std::uint64_t operator()(std::uint64_t bits, unsigned dim) const noexcept {
    return dimension(dim)(bits);
  }

 private:
  std::uint64_t base_;
};

/// Exact nested uniform scrambling in base 2 (Owen 1995). Each node of the
/// binary tree of dyadic intervals (a depth and the digits above it) gets an
/// independent random flip: digit b of the output is digit b of the input
/// XOR hash(seed, dim, depth, all higher digits of the input). The node is
/// encoded as the higher digits below a marker bit at position depth, so
/// the 64 nodes a word visits have distinct keys. One hash per digit (64 per
/// coordinate): the reference scrambler; HashOwenScrambler is the fast one.
class OwenScrambler {
 public:
  class Dimension {
   public:
    STRATUM_HOST_DEVICE explicit constexpr Dimension(std::uint64_t key) noexcept
        : mixed_(mix64(key + 0x9e3779b97f4a7c15ULL)) {}

    /// The random flip of the node at `depth` (0 = root: the first digit)
    /// whose higher digits are `prefix` (depth bits).
    STRATUM_HOST_DEVICE constexpr bool flip(unsigned depth, std::uint64_t prefix) const noexcept {
      return (base2_detail::keyed_word(mixed_, prefix | (std::uint64_t{1} << depth)) >> 63) != 0;
    }
    STRATUM_HOST_DEVICE constexpr std::uint64_t operator()(std::uint64_t bits) const noexcept {
      std::uint64_t flips = 0;
      for (unsigned depth = 0; depth < 64; ++depth) {
        const std::uint64_t prefix = depth == 0 ? 0 : bits >> (64 - depth);
        flips |= static_cast<std::uint64_t>(flip(depth, prefix)) << (63 - depth);
      }
      return bits ^ flips;
    }

   private:
    std::uint64_t mixed_;
  };

  STRATUM_HOST_DEVICE explicit constexpr OwenScrambler(std::uint64_t seed) noexcept
      : base_(hash64(seed, 0x6f77656eULL /* "owen" */)) {}

  STRATUM_HOST_DEVICE constexpr Dimension dimension(unsigned dim) const noexcept {
    return Dimension(base2_detail::dimension_key(base_, dim));
  }
  STRATUM_HOST_DEVICE constexpr std::uint64_t operator()(std::uint64_t bits, unsigned dim) const noexcept {
    return dimension(dim)(bits);
  }

 private:
  std::uint64_t base_;
};

/// Hash-based Owen scrambling (Burley 2020). On the bit-reversed word r
/// every step (r += a, r ^= r·K with K even, r *= m with m odd) changes bit j
/// only by a function of bits below j: in the original order, each digit is
/// flipped by a function of the higher digits, which is a nested (Owen)
/// scramble; the hash decides how random those flips look.
///
/// 64-bit extension: the same steps are done in 64-bit arithmetic with
/// constants whose low halves are Vegdahl's 32-bit constants (high halves
/// from the hexadecimal digits of π) and with a key whose low half is the
/// 32-bit seed. Because bits 0..31 of sums and products depend only on
/// bits 0..31 of the operands, the top 32 digits of the result equal the
/// published 32-bit scramble with seed = low half of the key, and the low
/// 32 digits are flipped by 64-bit products that mix all higher digits.
/// So all 53 digits of a double (and all 64 of the word) are scrambled,
/// and points with indices ≥ 2^32 are scrambled as well as the first ones.
class HashOwenScrambler {
 public:
  static constexpr std::uint64_t k1 = 0x243f6a883d20adeaULL;
  static constexpr std::uint64_t k2 = 0x85a308d305526c56ULL;
  static constexpr std::uint64_t k3 = 0x13198a2e53a22864ULL;

  class Dimension {
   public:
    STRATUM_HOST_DEVICE explicit constexpr Dimension(std::uint64_t key) noexcept
        : add_(key), multiply_((key & 0xffffffff00000000ULL) | ((key & 0xffffffffULL) >> 16) | 1) {}

    /// The scramble on a bit-reversed word (returns a bit-reversed word).
    STRATUM_HOST_DEVICE constexpr std::uint64_t scramble_reversed(std::uint64_t r) const noexcept {
      return HashOwenScrambler::scramble_reversed(r, add_, multiply_);
    }
    STRATUM_HOST_DEVICE constexpr std::uint64_t operator()(std::uint64_t bits) const noexcept {
      return reverse_bits64(scramble_reversed(reverse_bits64(bits)));
    }
    /// The 32-bit seed whose published scramble gives the top 32 digits.
    STRATUM_HOST_DEVICE constexpr std::uint32_t seed32() const noexcept { return static_cast<std::uint32_t>(add_); }
    /// The dimension's constants in the steps (for bulk code that runs them
    /// on vectors of words).
    STRATUM_HOST_DEVICE constexpr std::uint64_t addend() const noexcept { return add_; }
    STRATUM_HOST_DEVICE constexpr std::uint64_t multiplier() const noexcept { return multiply_; }

   private:
    std::uint64_t add_;
    std::uint64_t multiply_;
  };

  /// The steps on a bit-reversed word r with a dimension's addend and
  /// (odd) multiplier: the whole hash, in one place.
  STRATUM_HOST_DEVICE static constexpr std::uint64_t scramble_reversed(std::uint64_t r, std::uint64_t addend,
                                                                       std::uint64_t multiplier) noexcept {
    r ^= r * k1;
    r += addend;
    r *= multiplier;
    r ^= r * k2;
    r ^= r * k3;
    return r;
  }

  /// Dimensions whose bound scrambler is kept (computed at construction);
  /// dimension(dim) derives the others on each call.
  static constexpr unsigned cached_dimensions = 16;

  STRATUM_HOST_DEVICE explicit constexpr HashOwenScrambler(std::uint64_t seed) noexcept
      : base_(base_key(seed)), cache_(bind_first(base_, std::make_index_sequence<cached_dimensions>{})) {}

  /// The key of dimension `dim` under `seed`, alone: dimension(dim) of
  /// HashOwenScrambler(seed) is Dimension(dimension_key(seed, dim)).
  STRATUM_HOST_DEVICE static constexpr std::uint64_t dimension_key(std::uint64_t seed, unsigned dim) noexcept {
    return base2_detail::dimension_key(base_key(seed), dim);
  }

  STRATUM_HOST_DEVICE constexpr Dimension dimension(unsigned dim) const noexcept {
    return dim < cached_dimensions ? cache_[dim] : Dimension(base2_detail::dimension_key(base_, dim));
  }
  STRATUM_HOST_DEVICE constexpr std::uint64_t operator()(std::uint64_t bits, unsigned dim) const noexcept {
    return dimension(dim)(bits);
  }

 private:
  STRATUM_HOST_DEVICE static constexpr std::uint64_t base_key(std::uint64_t seed) noexcept {
    return hash64(seed, 0x6f68617368ULL /* "ohash" */);
  }
  template <std::size_t... dims>
  STRATUM_HOST_DEVICE static constexpr std::array<Dimension, sizeof...(dims)> bind_first(
      std::uint64_t base, std::index_sequence<dims...>) noexcept {
    return {Dimension(base2_detail::dimension_key(base, static_cast<unsigned>(dims)))...};
  }

  std::uint64_t base_;
  std::array<Dimension, cached_dimensions> cache_;
};

}  // namespace stratum
