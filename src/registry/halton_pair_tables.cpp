#include "stratum/registry/halton_pair_tables.hpp"

#include <algorithm>

#include "stratum/randomizers/digit_permutation.hpp"
#include "stratum/util/hash.hpp"
#include "stratum/util/real.hpp"

namespace stratum {

namespace {

// π_j(0) of ShuffledPermutationRule: digit 0 traced back through the swaps
// i = 1 … b − 1 as the rule's image() does, without branches or 128-bit
// products (j_1 = ⌊2h/2^64⌋ is h's top bit, j_2 = ⌊3h/2^64⌋ is
// high_of_three_times(h)). Fixed trip counts (64 and 48, multiples of 8):
// vectorized without remainder loops.
[[gnu::always_inline]] inline void images_of_zero(std::uint64_t dimension_key, std::uint32_t base,
                                                  std::uint8_t* out) noexcept {
  using Rule = digits_detail::ShuffledPermutationRule;
  if (base == 2) {
    for (unsigned j = 0; j < 64; ++j) {  // digit 0 moves to 1 exactly when j_1 = 0
      const std::uint64_t h = Rule::swap_word(hash64_extend(dimension_key, j), 1);
      out[j] = static_cast<std::uint8_t>(1 - (h >> 63));
    }
    return;
  }
  for (unsigned j = 0; j < 48; ++j) {
    const std::uint64_t key = hash64_extend(dimension_key, j);
    const std::uint32_t j1 = static_cast<std::uint32_t>(Rule::swap_word(key, 1) >> 63);
    const std::uint32_t j2 = HaltonPairTables::high_of_three_times(Rule::swap_word(key, 2));
    std::uint32_t at = j1 == 0 ? 1 : 0;       // swap 1 from digit 0
    at = at == 2 ? j2 : (at == j2 ? 2 : at);  // swap 2
    out[j] = static_cast<std::uint8_t>(at);
  }
}

// The same loops where AVX-512DQ multiplies 64-bit lanes: GCC vectorizes them 8 positions at a time.
[[gnu::target("avx512f,avx512dq,avx512vl")]] void images_of_zero_avx512(std::uint64_t dimension_key, std::uint32_t base,
                                                                        std::uint8_t* out) noexcept {
  images_of_zero(dimension_key, base, out);
}

}  // namespace

void HaltonPairTables::zero_images_portable(std::uint64_t dimension_key, std::uint32_t base,
                                            std::uint8_t* out) noexcept {
  images_of_zero(dimension_key, base, out);
}

bool HaltonPairTables::zero_images_vectorized() noexcept {
  static const bool supported =
      __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl");
  return supported;
}

void HaltonPairTables::zero_images(std::uint64_t dimension_key, std::uint32_t base, std::uint8_t* out) noexcept {
  if (zero_images_vectorized()) return images_of_zero_avx512(dimension_key, base, out);
  images_of_zero(dimension_key, base, out);
}

HaltonPairTables::HaltonPairTables() {
  for (unsigned c = 0; c < 2; ++c) weights_[c] = digits_detail::digit_weights(c == 0 ? 2 : 3);
}

void HaltonPairTables::build(std::uint64_t seed, std::uint64_t n, Set& set, unsigned coordinates) const noexcept {
  using u128 = unsigned __int128;
  // K(b) and m(b) of digits.hpp for bases 2 and 3, as constants.
  static constexpr unsigned positions_of[2] = {digits_detail::digit_count(2), digits_detail::digit_count(3)};
  static constexpr unsigned chunk_of[2] = {digits_detail::chunk_digits(2), digits_detail::chunk_digits(3)};
  static_assert(positions_of[0] <= 64 && positions_of[1] <= 64);  // zero_images' array below
  const digits_detail::ShuffledPermutationRule rule(seed);        // RandomDigitPermutations' permutations
  for (unsigned c = 0; c < coordinates; ++c) {
    const std::uint32_t base = c + 2;
    const unsigned positions = positions_of[c], chunk = chunk_of[c];
    const u128* weight = weights_[c].data();
    unsigned used = 0;  // positions where some index < n has a non-zero digit (≤ chunk, as n ≤ base^chunk)
    for (std::uint64_t r = n - 1; r != 0; r /= base) ++used;
    std::uint32_t images[3];
    for (unsigned j = 0; j < used; ++j) {
      rule.permutation(c, j, base, images);
      for (std::uint32_t a = 0; a < base; ++a) set.low[c][j][a] = std::uint64_t{images[a]} * weight[j];
    }
    // Past the used positions every index has digit 0: π_j(0)·W_j, summed in
    // 128 bits per chunk (the rest of the first chunk kept whole, each later
    // chunk truncated to its top 64 bits, as digits.hpp's tables do).
    std::uint8_t zero[64];  // π_j(0), read for j ≥ used
    zero_images(rule.dimension_key(c), base, zero);
    const auto sum_of = [&](unsigned from, unsigned to) {  // Σ π_j(0)·W_j over from ≤ j < to
      u128 sum = 0;
      for (unsigned j = from; j < to; ++j) sum += std::uint64_t{zero[j]} * weight[j];
      return sum;
    };
    std::uint64_t tail = 0;
    for (unsigned start = chunk; start < positions; start += chunk)
      tail += static_cast<std::uint64_t>(sum_of(start, std::min(start + chunk, positions)) >> 64);
    set.first_chunk_rest[c] = sum_of(used, chunk);
    set.tail[c] = tail;
    set.positions[c] = used;
  }
  set.coordinates = coordinates;
}

std::array<double, 2> HaltonPairTables::point(const Set& set, std::uint64_t index) noexcept {
  std::array<double, 2> point{0.0, 0.0};
  for (unsigned c = 0; c < set.coordinates; ++c) {
    const std::uint32_t base = c == 0 ? 2 : 3;
    unsigned __int128 sum = set.first_chunk_rest[c];
    std::uint64_t rest = index;
    for (unsigned j = 0; j < set.positions[c]; ++j) sum += set.low[c][j][rest % base], rest /= base;
    const std::uint64_t fraction = static_cast<std::uint64_t>(sum >> 64) + set.tail[c];
    point[c] = to_unit<double>(digits_detail::fraction_to_double(fraction));
  }
  return point;
}

void HaltonPairTables::fill(std::uint64_t seed, std::uint64_t start, std::uint64_t n, double* out) const {
  if (start + n <= max_points) {
    Set set;
    build(seed, start + n, set);
    for (std::uint64_t i = 0; i < n; ++i) {
      const std::array<double, 2> p = point(set, start + i);
      out[2 * i] = p[0], out[2 * i + 1] = p[1];
    }
    return;
  }
  // The registry's scrambler for these bases and indices, without its
  // request handling: each point straight from RandomDigitPermutations.
  const RandomDigitPermutations permutations(seed, {2, 3}, start + n - 1);
  for (std::uint64_t i = 0; i < n; ++i)
    out[2 * i] = permutations.sample(start + i, 0), out[2 * i + 1] = permutations.sample(start + i, 1);
}

}  // namespace stratum
