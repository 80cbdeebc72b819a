#pragma once
/// Counter-based randomness: every random number is a pure function of
/// (seed, counters), so results never depend on call order or thread count.
/// The mixer is the finalizer of SplitMix64 (Steele, Lea, Flood 2014,
/// "Fast splittable pseudorandom number generators"), which passes BigCrush
/// when applied to a counter.
#include <cstdint>

#include "stratum/util/host_device.hpp"

namespace stratum {

/// Bijective 64-bit mixer (SplitMix64 finalizer).
STRATUM_HOST_DEVICE constexpr std::uint64_t mix64(std::uint64_t x) noexcept {
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  x ^= x >> 31;
  return x;
}

/// Hash of a seed and any number of 64-bit counters.
STRATUM_HOST_DEVICE constexpr std::uint64_t hash64(std::uint64_t seed) noexcept {
  return mix64(seed + 0x9e3779b97f4a7c15ULL);
}
template <class... Rest>
STRATUM_HOST_DEVICE constexpr std::uint64_t hash64(std::uint64_t seed, std::uint64_t first, Rest... rest) noexcept {
  return hash64(mix64(seed + 0x9e3779b97f4a7c15ULL) ^ (first * 0xd1342543de82ef95ULL + 0x632be59bd9b4e019ULL), rest...);
}

/// hash64(seed, c₁, …, c_k, c) from h = hash64(seed, c₁, …, c_k): one mix
/// instead of k + 2, for loops where only the last counters vary (hash64 is
/// a chain: each counter is xored into the previous mix).
STRATUM_HOST_DEVICE constexpr std::uint64_t hash64_extend(std::uint64_t h, std::uint64_t c) noexcept {
  return mix64((h ^ (c * 0xd1342543de82ef95ULL + 0x632be59bd9b4e019ULL)) + 0x9e3779b97f4a7c15ULL);
}

/// Top 53 bits of a 64-bit word as a double in [0, 1).
STRATUM_HOST_DEVICE constexpr double bits_to_double(std::uint64_t bits) noexcept {
  return static_cast<double>(bits >> 11) * 0x1.0p-53;
}
/// Top 24 bits of a 64-bit word as a float in [0, 1).
STRATUM_HOST_DEVICE constexpr float bits_to_float(std::uint64_t bits) noexcept {
  return static_cast<float>(bits >> 40) * 0x1.0p-24f;
}

/// Uniform value in [0, 1) for (seed, counters).
template <class Real = double, class... Counters>
STRATUM_HOST_DEVICE constexpr Real uniform01(std::uint64_t seed, Counters... counters) noexcept {
  const std::uint64_t bits = hash64(seed, static_cast<std::uint64_t>(counters)...);
  if constexpr (sizeof(Real) == sizeof(float)) return bits_to_float(bits);
  else return bits_to_double(bits);
}

/// uniform01(seed, index, 0) and, where coordinates is 2, uniform01(seed,
/// index, 1), from m = hash64(seed): three mixes for the pair instead of
/// eight (hash64 is a chain: hash64_extend), for per-pixel draws.
template <int coordinates = 2>
STRATUM_HOST_DEVICE constexpr void uniform01_pair(std::uint64_t m, std::uint64_t index, double* out) noexcept {
  const std::uint64_t t = hash64_extend(m, index);
  out[0] = bits_to_double(hash64_extend(t, 0));
  if constexpr (coordinates == 2) out[1] = bits_to_double(hash64_extend(t, 1));
}

/// Unbiased integer in [0, bound) for (seed, counters): Lemire's multiply-shift
/// with rejection (Lemire 2019, "Fast random integer generation in an interval"),
/// drawing further words from the same counter stream when it rejects.
template <class... Counters>
STRATUM_HOST_DEVICE constexpr std::uint64_t uniform_below(std::uint64_t bound, std::uint64_t seed,
                                                          Counters... counters) noexcept {
  const std::uint64_t key = hash64(seed, static_cast<std::uint64_t>(counters)...);
  for (std::uint64_t attempt = 0;; ++attempt) {
    const std::uint64_t word = hash64(key, attempt);
    const unsigned __int128 product = static_cast<unsigned __int128>(word) * bound;
    const auto low = static_cast<std::uint64_t>(product);
    // threshold = 2^64 mod bound < bound, so low ≥ bound accepts without the
    // (slow) division; it is computed only in the rare case low < bound.
    if (low >= bound || low >= (0 - bound) % bound) return static_cast<std::uint64_t>(product >> 64);
  }
}

}  // namespace stratum
