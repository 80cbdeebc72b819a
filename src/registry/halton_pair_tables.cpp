#include "stratum/registry/halton_pair_tables.hpp"

#include <algorithm>
#include <array>

#include "stratum/randomizers/digit_permutation.hpp"
#include "stratum/util/hash.hpp"
#include "stratum/util/real.hpp"

namespace stratum {

namespace {

using u128 = unsigned __int128;
using Rule = digits_detail::ShuffledPermutationRule;

constexpr unsigned positions3 = digits_detail::digit_count(3);  // 41
constexpr unsigned chunk3 = digits_detail::chunk_digits(3);     // 7
static_assert(chunk3 == HaltonPairTables::max_positions3 && positions3 <= 48);
static_assert(digits_detail::digit_count(2) == 64 && digits_detail::chunk_digits(2) == 12);

// z·W_j of base 3 for z = 0, 1, 2 (digits.hpp's weights), at compile time.
constexpr auto weight_times3 = [] {
  std::array<std::array<u128, 3>, positions3> table{};
  for (unsigned j = 0; j < positions3; ++j)
    for (unsigned z = 0; z < 3; ++z) table[j][z] = z * digits_detail::digit_weight(3, j);
  return table;
}();

// π_j(0)·W_j of base 3 by swap code (HaltonPairTables::code_permutations3).
constexpr auto zero_weight3 = [] {
  std::array<std::array<u128, 6>, positions3> table{};
  for (unsigned j = 0; j < positions3; ++j)
    for (unsigned code = 0; code < 6; ++code)
      table[j][code] = weight_times3[j][HaltonPairTables::code_permutations3[code][0]];
  return table;
}();

// The swaps of ShuffledPermutationRule without branches or 128-bit products
// (j_1 = ⌊2h/2^64⌋ is h's top bit, j_2 = ⌊3h/2^64⌋ is high_of_three_times(h)),
// in fixed trip counts (64 and 48, multiples of 8): vectorized without
// remainder loops. Base 2: π_j(0), bit 63 − j of a word.
[[gnu::always_inline]] inline std::uint64_t bits_of_zero2(std::uint64_t dimension_key) noexcept {
  std::uint64_t bits = 0;
  for (unsigned j = 0; j < 64; ++j) {  // digit 0 moves to 1 exactly when j_1 = 0
    const std::uint64_t h = Rule::swap_word(hash64_extend(dimension_key, j), 1);
    bits |= ((h >> 63) ^ 1) << (63 - j);
  }
  return bits;
}

// The swaps of base 3's permutation at every position, as code j_1 + 2·j_2
// (HaltonPairTables::code_permutations3 turns a code into the permutation).
[[gnu::always_inline]] inline void swap_codes_of3(std::uint64_t dimension_key, std::uint64_t* out) noexcept {
  for (unsigned j = 0; j < 48; ++j) {
    const std::uint64_t key = hash64_extend(dimension_key, j);
    const std::uint32_t j1 = static_cast<std::uint32_t>(Rule::swap_word(key, 1) >> 63);
    const std::uint32_t j2 = HaltonPairTables::high_of_three_times(Rule::swap_word(key, 2));
    out[j] = j1 + 2 * j2;
  }
}

// The same loops where AVX-512DQ multiplies 64-bit lanes: GCC vectorizes them 8 positions at a time.
[[gnu::target("avx512f,avx512dq,avx512vl,prefer-vector-width=512")]] std::uint64_t bits_of_zero2_avx512(
    std::uint64_t dimension_key) noexcept {
  return bits_of_zero2(dimension_key);
}
[[gnu::target("avx512f,avx512dq,avx512vl,prefer-vector-width=512")]] void swap_codes_of3_avx512(
    std::uint64_t dimension_key, std::uint64_t* out) noexcept {
  swap_codes_of3(dimension_key, out);
}

}  // namespace

std::uint64_t HaltonPairTables::zero_bits2_portable(std::uint64_t dimension_key) noexcept {
  return bits_of_zero2(dimension_key);
}

void HaltonPairTables::swap_codes3_portable(std::uint64_t dimension_key, std::uint64_t* out) noexcept {
  swap_codes_of3(dimension_key, out);
}

bool HaltonPairTables::vectorized() noexcept {
  static const bool supported =
      __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl");
  return supported;
}

std::uint64_t HaltonPairTables::zero_bits2(std::uint64_t dimension_key) noexcept {
  return vectorized() ? bits_of_zero2_avx512(dimension_key) : bits_of_zero2(dimension_key);
}

void HaltonPairTables::swap_codes3(std::uint64_t dimension_key, std::uint64_t* out) noexcept {
  if (vectorized()) return swap_codes_of3_avx512(dimension_key, out);
  swap_codes_of3(dimension_key, out);
}

std::uint64_t HaltonPairTables::base2_word(std::uint64_t seed) noexcept {
  return zero_bits2(Rule(seed).dimension_key(0));  // RandomDigitPermutations' permutations
}

void HaltonPairTables::build(std::uint64_t seed, std::uint64_t n, Set& set, unsigned coordinates) const noexcept {
  const Rule rule(seed);  // RandomDigitPermutations' permutations
  // Base 2: the digit-0 images are the whole permutation (see the header).
  set.zero_bits2 = zero_bits2(rule.dimension_key(0));
  set.coordinates = coordinates;
  if (coordinates < 2) return;
  // Base 3: positions where some index < n has a non-zero digit (≤ chunk3, as n ≤ 3^chunk3).
  unsigned used = 0;
  for (std::uint64_t r = n - 1; r != 0; r /= 3) ++used;
  std::uint64_t code[48];  // each position's swaps: its permutation
  swap_codes3(rule.dimension_key(1), code);
  for (unsigned j = 0; j < used; ++j)
    for (std::uint32_t a = 0; a < 3; ++a) set.low3[j][a] = weight_times3[j][code_permutations3[code[j]][a]];
  // Past the used positions every index has digit 0: π_j(0)·W_j, summed in
  // 128 bits per chunk (the rest of the first chunk kept whole, each later
  // chunk truncated to its top 64 bits, as digits.hpp's tables do).
  u128 rest = 0;
  for (unsigned j = used; j < chunk3; ++j) rest += zero_weight3[j][code[j]];
  std::uint64_t tail = 0;
  for (unsigned start = chunk3; start < positions3; start += chunk3) {
    u128 sum = 0;
    for (unsigned j = start; j < std::min(start + chunk3, positions3); ++j) sum += zero_weight3[j][code[j]];
    tail += static_cast<std::uint64_t>(sum >> 64);
  }
  set.first_chunk_rest3 = rest;
  set.tail3 = tail;
  set.positions3 = used;
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
