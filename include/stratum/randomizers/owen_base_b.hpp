#pragma once
/// Nested uniform scrambling in base b for radical-inverse sequences (Owen
/// 1995, "Randomly permuted (t,m,s)-nets and (t,s)-sequences"): the output
/// digit at position j is π_{j, a_0…a_(j−1)}(a_j), a permutation chosen
/// afresh for every prefix of higher output digits (the index's lower
/// digits). Nets stay nets (Halton's mixed-base elementary intervals
/// survive), every point is uniform and, unlike a permutation per position,
/// the scrambling randomizes within every elementary interval, which gives
/// Owen's variance bounds (Owen 1997, "Monte Carlo variance of scrambled net
/// quadrature").
///
/// There are too many nodes (j, p) to tabulate (p = index mod b^j codes the
/// prefix), so each node's permutation is drawn from hashes, split as
/// π_{j,p}(a) = (m · τ_{j,p}(a) + s_{j,p}) mod b with τ(0) = 0. Every
/// permutation is exactly one shift of one permutation fixing 0, so π is
/// uniform when the shift s = π(0) and τ are:
///  - s_{j,p}, for every position j, comes from words of the prefix alone,
///    w_k = hash(key_k, p): in base 2 bit j of one word (exact), in base b
///    digit t of word k = ⌊j / D⌋ read as a base-b fraction, t = j mod D,
///    D = D(b) digits a word with b^D ≤ 2^30 (their joint law within 2^-34
///    of uniform in total variation).
///  - τ_{j,p} (only where the index's digit is not 0), from one hash of
///    (key, j, p): b = 2, the identity; 3 ≤ b ≤ 24, a uniform permutation of
///    {1..b−1} by a Fisher–Yates shuffle (Durstenfeld 1964) whose draws are
///    the word's mixed-radix digits in radices 2, 3, …, b−1 (two more words
///    past radix 12 and 18); b > 24, 1 + σ(a − 1) with σ a keyed bijection
///    of {0..b−2} by cycle walking (Black, Rogaway 2002; as Kensler 2013's
///    permute) and m uniform in {1..b−1} for prime b (m = 1 otherwise): each
///    image uniform and, for prime b, every pair of images uniform over
///    distinct pairs, all the variance of scrambled-net quadrature depends
///    on (Owen 1997: a sum over pairs of points).
/// Why the split: a node's prefix p < b^j, and the prefixes index mod b^j of
/// one point change only at its nonzero digits, so a point with k nonzero
/// digits reads the words of k + 1 prefixes and hashes τ k times, instead of
/// one hash for each of the K(b) positions (64 in base 2); past its last
/// nonzero digit every image is a shift of the same prefix, summed from each
/// word at once. Every one of the K(b) positions of digits.hpp is scrambled.
///
/// Device code (docs/gpu.md): a sample reads the keys and weights through a
/// View (pointers, trivially copyable) that a kernel takes by value; view()
/// points into the scrambler, view(copy) into copies that `copy` makes.
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "stratum/randomizers/digits.hpp"
#include "stratum/util/bits.hpp"
#include "stratum/util/hash.hpp"

namespace stratum {

/// Nested uniform (Owen) scrambling of radical inverses in any base ("owen"):
/// dimension `dim` uses base bases[dim]; sample(index, dim) depends only on
/// (seed, dim, index). Construction computes a few keys per dimension; a
/// sample allocates nothing.
class BaseBOwenScrambler {
 public:
  BaseBOwenScrambler(std::uint64_t seed, const std::vector<std::uint32_t>& bases) {
    digits_detail::require_digit_bases(bases);
    dims_.reserve(bases.size());
    std::size_t key_count = 0;
    for (const std::uint32_t base : bases) {
      const unsigned positions = digits_detail::digit_count(base), per_word = word_digits(base);
      const unsigned words = (positions + per_word - 1) / per_word;
      dims_.push_back({base, positions, per_word, words, key_count, FastDivider(base), is_prime(base),
                       base == 2 ? nullptr : digits_detail::shared_digit_weights(base),
                       base == 2 ? 0 : power_of(base, per_word)});
      key_count += 1 + words + 1;  // τ's key, the prefix words' keys, the word of prefix 0
    }
    keys_.resize(key_count);
    keys_for(seed, keys_.data());
  }

  /// The keys of `seed` (key_count() words) into `keys`, as the constructor
  /// computes its own, for dimensions 0 … count − 1 (the others' keys are
  /// left as they are): with view(keys), the scrambler of that seed without
  /// constructing one (a renderer rekeys per pixel and dimension).
  void keys_for(std::uint64_t seed, std::uint64_t* keys, unsigned count = ~0u) const noexcept {
    // hash64(key, dim) = hash64_extend(hash64(key), dim): the first mix shared by the dimensions.
    const std::uint64_t key_mix = hash64(hash64(seed, 0x6f77656e62ULL /* "owenb" */));
    for (unsigned dim = 0; dim < dims_.size() && dim < count; ++dim) {
      // τ's key (base 2 has no τ), then one key per prefix word: hash64(key, dim, k); then the first word of
      // prefix 0, which every point reads first (its digit 0's node), hashed once here instead of per point.
      const Dimension& d = dims_[dim];
      const std::uint64_t dimension_key = hash64_extend(key_mix, dim);
      std::uint64_t* own = keys + d.first_key;
      for (unsigned k = d.base == 2 ? 1 : 0; k <= d.prefix_words; ++k) own[k] = hash64_extend(dimension_key, k);
      own[1 + d.prefix_words] = node_word(own[1], 0);
    }
  }
  std::size_t key_count() const noexcept { return keys_.size(); }

  unsigned dimensions() const noexcept { return static_cast<unsigned>(dims_.size()); }
  std::uint32_t base(unsigned dim) const noexcept { return dims_[dim].base; }

  /// The scrambled radical inverse of `index` as a 64-bit binary fraction.
  std::uint64_t fraction(std::uint64_t index, unsigned dim) const noexcept { return view().fraction(index, dim); }

  /// The scrambled radical inverse as a double or float in [0, 1).
  template <class Real = double>
  Real sample(std::uint64_t index, unsigned dim) const noexcept {
    return view().template sample<Real>(index, dim);
  }

  /// π_{position, prefix}(digit) of dimension dim, where prefix = index mod
  /// b^position codes the index's digits below `position` (for tests and
  /// oracles).
  std::uint32_t permute_digit(unsigned dim, unsigned position, std::uint64_t prefix,
                              std::uint32_t digit) const noexcept {
    const Dimension& d = dims_[dim];
    const std::uint64_t* keys = keys_.data() + d.first_key;
    if (d.base == 2) return digit ^ static_cast<std::uint32_t>((node_word(keys[1], prefix) >> (63 - position)) & 1);
    const unsigned t = position % d.word_digits;
    const std::uint64_t word = node_word(keys[1 + position / d.word_digits], prefix);
    const std::uint32_t shift = word_digit(d, word, power_of(d.base, t + 1));
    return digit == 0 ? shift : image(d, keys[0], position, prefix, digit, shift);
  }

 private:
  static constexpr std::uint64_t golden = 0x9e3779b97f4a7c15ULL;

  struct Dimension {
    std::uint32_t base;
    unsigned positions;     // K(b)
    unsigned word_digits;   // D(b): shifts read from one prefix word
    unsigned prefix_words;  // ⌈K(b) / D(b)⌉: words of one prefix
    std::size_t first_key;
    FastDivider divider;
    bool prime;
    const digits_detail::u128* weights;  // the base's W_j (b > 2), shared for the process
    std::uint64_t word_power;            // b^D (b > 2)
  };

 public:
  /// The per-sample path: the scrambler's arrays by pointer.
  class View {
   public:
    STRATUM_HOST_DEVICE View(const Dimension* dims, const std::uint64_t* keys) noexcept : dims_(dims), keys_(keys) {}

    /// The scrambled radical inverse of `index` as a 64-bit binary fraction.
    STRATUM_HOST_DEVICE std::uint64_t fraction(std::uint64_t index, unsigned dim) const noexcept {
      const Dimension& d = dims_[dim];
      const std::uint64_t* keys = keys_ + d.first_key;
      if (d.base == 2) return fraction2(index, keys[1], keys[2]);  // small: inlined where fraction is
      return fraction_b(d, keys, index);
    }
    template <class Real = double>
    STRATUM_HOST_DEVICE Real sample(std::uint64_t index, unsigned dim) const noexcept {
      return to_unit<Real>(digits_detail::fraction_to_double(fraction(index, dim)));
    }

   private:
    STRATUM_HOST_DEVICE static std::uint64_t fraction_b(const Dimension& d, const std::uint64_t* keys,
                                                        std::uint64_t index) noexcept {
      const digits_detail::u128* weights = d.weights;
      const std::uint32_t b = d.base;
      digits_detail::u128 sum = 0;
      std::uint64_t prefix = 0, rest = index;
      std::uint64_t power = 1;                        // b^j modulo 2^64: only multiplies digits 0 once it wraps
      unsigned j = 0, t = 0;                          // position, and its digit in its prefix word
      std::uint64_t word_power = 1;                   // b^t
      const std::uint64_t* word_key = keys + 1;       // of word ⌊j / D⌋
      std::uint64_t word = keys[1 + d.prefix_words];  // word 0 of prefix 0
      bool fresh = true;                              // `word` is word ⌊j / D⌋ of `prefix`
      // The index's digits, up to its last nonzero one, one at a time.
      for (; rest != 0; ++j, ++t, power *= b, word_power *= b) {
        if (t == d.word_digits) t = 0, word_power = 1, ++word_key, fresh = false;
        const std::uint64_t next = d.divider.quotient(rest);
        const auto digit = static_cast<std::uint32_t>(rest - next * b);
        rest = next;
        if (!fresh) word = node_word(*word_key, prefix), fresh = true;
        const std::uint32_t shift = word_digit(d, word, word_power * b);
        // Both computed and one selected: whether a digit is 0 is data, a branch on it mispredicts.
        const std::uint32_t permuted = image(d, keys[0], j, prefix, digit == 0 ? 1 : digit, shift);
        const std::uint32_t image_j = digit == 0 ? shift : permuted;
        sum += static_cast<digits_detail::u128>(image_j) * weights[j];
        if (digit != 0) prefix += digit * power, fresh = false;
      }
      // Past it every digit is 0 and the prefix is the index: the images are
      // the shifts, the rest of each word's digits as one integer,
      // ⌊frac(w·b^t / 2^64)·b^(c−t)⌋ for digits t..c−1 (their weights sum
      // to that integer times the weight of digit c−1, up to the floors).
      if (t == d.word_digits) t = 0, word_power = 1, ++word_key, fresh = false;
      for (unsigned first = j - t; first < d.positions; first += d.word_digits, t = 0, word_power = 1, ++word_key) {
        const unsigned count = d.positions - first < d.word_digits ? d.positions - first : d.word_digits;
        const std::uint64_t w = fresh ? word : node_word(*word_key, prefix);  // fresh: index 0's first word
        fresh = false;
        const auto below = static_cast<std::uint64_t>(static_cast<digits_detail::u128>(w) * word_power);
        const std::uint64_t span = count == d.word_digits && t == 0 ? d.word_power : power_of(b, count - t);
        const auto digits = static_cast<std::uint64_t>((static_cast<digits_detail::u128>(below) * span) >> 64);
        sum += static_cast<digits_detail::u128>(digits) * weights[first + count - 1];
      }
      return static_cast<std::uint64_t>(sum >> 64);
    }

    // Base 2: π(a) = a ⊕ s, so the fraction is the reversed index ⊕ the
    // shifts; the positions lo..hi that share a prefix take bits 63−hi..63−lo
    // of its word (position j is bit 63 − j, the fraction's order).
    // zero_word is the word of prefix 0, the first segment's.
    STRATUM_HOST_DEVICE static std::uint64_t fraction2(std::uint64_t index, std::uint64_t word_key,
                                                       std::uint64_t zero_word) noexcept {
      std::uint64_t flips = 0, prefix = 0, rest = index;
      unsigned lo = 0;
      for (;;) {
        const unsigned hi = rest == 0 ? 63u : static_cast<unsigned>(countr_zero64(rest));
        const std::uint64_t word = prefix == 0 ? zero_word : node_word(word_key, prefix);
        flips |= word & ((~std::uint64_t{0} >> lo) & (~std::uint64_t{0} << (63 - hi)));
        if (rest == 0 || hi == 63) break;
        prefix |= std::uint64_t{1} << hi;
        rest &= rest - 1;
        lo = hi + 1;
      }
      return reverse_bits64(index) ^ flips;
    }

    const Dimension* dims_;
    const std::uint64_t* keys_;
  };

  /// The per-sample path reading this object's arrays.
  View view() const noexcept { return View(dims_.data(), keys_.data()); }
  /// The per-sample path with the keys of another seed (keys_for).
  View view(const std::uint64_t* keys) const noexcept { return View(dims_.data(), keys); }
  /// The per-sample path reading copies: copy(data, count) copies `count`
  /// elements (trivially copyable) and returns the copy's address. The
  /// weights are copied once for all dimensions, and the copied dimensions
  /// point into that copy.
  template <class Copy>
  View view(Copy&& copy) const {
    std::vector<digits_detail::u128> weights;
    std::vector<std::size_t> offsets;
    for (const Dimension& d : dims_) {
      offsets.push_back(weights.size());
      if (d.weights) weights.insert(weights.end(), d.weights, d.weights + d.positions);
    }
    const digits_detail::u128* copied = weights.empty() ? nullptr : copy(weights.data(), weights.size());
    std::vector<Dimension> dims = dims_;
    for (std::size_t k = 0; k < dims.size(); ++k)
      if (dims[k].weights) dims[k].weights = copied + offsets[k];
    return View(copy(dims.data(), dims.size()), copy(keys_.data(), keys_.size()));
  }

 private:
  STRATUM_HOST_DEVICE static constexpr bool is_prime(std::uint32_t n) noexcept {
    for (std::uint32_t f = 2; f * f <= n; ++f)
      if (n % f == 0) return false;
    return n >= 2;
  }

  /// D(b): 64 in base 2 (a word's bits), else the largest D ≥ 1 with b^D ≤ 2^30.
  static constexpr unsigned word_digits_by_powers(std::uint32_t base) noexcept {
    if (base == 2) return 64;
    return digits_detail::digits_within(base, std::uint64_t{1} << 30);
  }
  static unsigned word_digits(std::uint32_t base) noexcept {
    static constexpr std::array<std::uint8_t, 64> small = [] {  // the common bases without the loop
      std::array<std::uint8_t, 64> counts{};
      for (std::uint32_t b = 2; b < counts.size(); ++b) counts[b] = static_cast<std::uint8_t>(word_digits_by_powers(b));
      return counts;
    }();
    return base < small.size() ? small[base] : word_digits_by_powers(base);
  }

  STRATUM_HOST_DEVICE static constexpr std::uint64_t power_of(std::uint64_t base, unsigned exponent) noexcept {
    std::uint64_t result = 1;
    for (; exponent != 0; exponent >>= 1, base *= base)
      if (exponent & 1) result *= base;
    return result;
  }

  // A word of (key, prefix): hash64_extend(key, prefix).
  STRATUM_HOST_DEVICE static constexpr std::uint64_t node_word(std::uint64_t key, std::uint64_t prefix) noexcept {
    return hash64_extend(key, prefix);
  }

  // Digit t of `word` read as a base-b fraction, ⌊w·b^(t+1) / 2^64⌋ mod b,
  // given b^(t+1) (≤ 2^30).
  STRATUM_HOST_DEVICE static std::uint32_t word_digit(const Dimension& d, std::uint64_t word,
                                                      std::uint64_t power_next) noexcept {
    const auto leading = static_cast<std::uint64_t>((static_cast<digits_detail::u128>(word) * power_next) >> 64);
    return static_cast<std::uint32_t>(leading - d.divider.quotient(leading) * d.base);
  }

  // π_{j,p}(digit) = (m·τ(digit) + shift) mod b for a nonzero digit (b > 2).
  STRATUM_HOST_DEVICE static std::uint32_t image(const Dimension& d, std::uint64_t tau_key, unsigned position,
                                                 std::uint64_t prefix, std::uint32_t digit,
                                                 std::uint32_t shift) noexcept {
    const std::uint32_t b = d.base;
    const std::uint64_t w = node_word(mix64(tau_key + (position + 1) * golden), prefix);
    std::uint64_t m = 1;
    std::uint32_t tau = 0;
    if (b <= 24) {
      // Fisher–Yates over the b − 1 elements 1..b−1 (swap i and j_i for
      // i = b−2 down to 1, elements counted from 0) with draws j_i ∈ [0, i]
      // read off a 64-bit fraction u as mixed-radix digits, j_i = ⌊u·(i+1)⌋,
      // u ← frac(u·(i+1)), for i = 1, 2, …: the order in which the image is
      // traced back through the swaps, so no array is needed. Radices 2–12,
      // 13–18 and 19–23 read three words (products 2^28.8, 2^23.7, 2^21.9).
      std::uint32_t position_of = digit - 1;
      std::uint64_t u = w;
      for (std::uint32_t i = 1; i + 1 < b; ++i) {
        if (i == 12) u = mix64(w + golden);
        if (i == 18) u = mix64(w + 2 * golden);
        const digits_detail::u128 product = static_cast<digits_detail::u128>(u) * (i + 1);
        const auto j = static_cast<std::uint32_t>(product >> 64);
        u = static_cast<std::uint64_t>(product);
        position_of = position_of == i ? j : (position_of == j ? i : position_of);
      }
      tau = 1 + position_of;
    } else {
      // A bijection of k-bit words (xor, odd multiply, xorshift and add are
      // each invertible mod 2^k), iterated until it lands below b − 1
      // (cycle walking): σ of {0..b−2}.
      const std::uint64_t w2 = mix64(w + golden);
      const unsigned bits = static_cast<unsigned>(bit_width64(b - 2));
      const std::uint32_t mask = (std::uint32_t{1} << bits) - 1;
      const auto flip = static_cast<std::uint32_t>(w2);
      const auto odd = static_cast<std::uint32_t>(w2 >> 32) | 1u;
      const auto offset = static_cast<std::uint32_t>(w);  // m takes w's leading bits
      std::uint32_t x = digit - 1;
      do {
        x = (x ^ flip) & mask;
        x = (x * odd) & mask;
        x ^= x >> (bits / 2);
        x = (x + offset) & mask;
        x = (x * 0x2c1b3c6du) & mask;
        x ^= x >> ((bits + 2) / 3);
      } while (x >= b - 1);
      tau = 1 + x;
      if (d.prime) m = 1 + static_cast<std::uint64_t>((static_cast<digits_detail::u128>(w) * (b - 1)) >> 64);
    }
    if (m == 1) return tau + shift < b ? tau + shift : tau + shift - b;
    const std::uint64_t x = m * tau + shift;  // < b² < 2^33: the divider's exact range
    return static_cast<std::uint32_t>(x - d.divider.quotient(x) * b);
  }

  std::vector<Dimension> dims_;
  std::vector<std::uint64_t> keys_;
};

}  // namespace stratum
