#pragma once
// The digit-0 images of the renderer's halton sets (PixelSampler::build_halton_set).
#include <cstdint>

namespace stratum::render {

/// ⌊3h / 2^64⌋ without a 128-bit product: how many of ⌈2^64/3⌉ and
/// ⌈2^65/3⌉ h reaches (a vector compare each).
constexpr std::uint32_t high_of_three_times(std::uint64_t h) noexcept {
  return std::uint32_t{h >= 0x5555555555555556ULL} + std::uint32_t{h >= 0xAAAAAAAAAAAAAAABULL};
}

/// π_j(0) of ShuffledPermutationRule for positions j < 64 (base 2) or
/// j < 48 (base 3, 41 used) of one dimension, from its dimension_key, into
/// out[0 … 63]: digit 0 traced back
/// through swaps i = 1 … b − 1 as the rule's image() does, written without
/// branches or 128-bit products (j_1 = ⌊2h/2^64⌋ is h's top bit, j_2 =
/// ⌊3h/2^64⌋ is high_of_three_times(h)) so that the positions' independent
/// hashes vectorize. The renderer's halton sets spend most of their time
/// here (≈ 100 positions past the digits the indices use, 2–3 hashes each;
/// the few positions below, which the caller permutes whole, cost little);
/// an AVX-512 copy (64-bit multiplies in vector registers) is chosen at run
/// time where the CPU has AVX-512DQ. Tested equal to image(), both copies.
void halton_zero_images(std::uint64_t dimension_key, std::uint32_t base, std::uint8_t* out) noexcept;
/// The portable copy (SSE2 cannot multiply 64-bit lanes: scalar), and
/// whether halton_zero_images takes the AVX-512 one on this CPU (for tests).
void halton_zero_images_portable(std::uint64_t dimension_key, std::uint32_t base, std::uint8_t* out) noexcept;
bool halton_zero_images_vectorized() noexcept;

}  // namespace stratum::render
