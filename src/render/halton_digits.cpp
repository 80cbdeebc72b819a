#include "halton_digits.hpp"

#include "stratum/randomizers/digit_permutation.hpp"
#include "stratum/util/hash.hpp"

namespace stratum::render {

namespace {

// Fixed trip counts (64 and 48, multiples of 8): vectorized without remainder loops.
[[gnu::always_inline]] inline void zero_images(std::uint64_t dimension_key, std::uint32_t base,
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
    const std::uint32_t j2 = high_of_three_times(Rule::swap_word(key, 2));
    std::uint32_t at = j1 == 0 ? 1 : 0;       // swap 1 from digit 0
    at = at == 2 ? j2 : (at == j2 ? 2 : at);  // swap 2
    out[j] = static_cast<std::uint8_t>(at);
  }
}

// The same loops where AVX-512DQ multiplies 64-bit lanes: GCC vectorizes them 8 positions at a time.
[[gnu::target("avx512f,avx512dq,avx512vl")]] void zero_images_avx512(std::uint64_t dimension_key, std::uint32_t base,
                                                                     std::uint8_t* out) noexcept {
  zero_images(dimension_key, base, out);
}

}  // namespace

void halton_zero_images_portable(std::uint64_t dimension_key, std::uint32_t base, std::uint8_t* out) noexcept {
  zero_images(dimension_key, base, out);
}

bool halton_zero_images_vectorized() noexcept {
  static const bool supported =
      __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl");
  return supported;
}

void halton_zero_images(std::uint64_t dimension_key, std::uint32_t base, std::uint8_t* out) noexcept {
  if (halton_zero_images_vectorized()) return zero_images_avx512(dimension_key, base, out);
  zero_images(dimension_key, base, out);
}

}  // namespace stratum::render
