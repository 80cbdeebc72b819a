#pragma once
/// Bit manipulation used by base-2 sequences and scramblers.
#include <bit>
#include <cstdint>
#include <type_traits>

#include "stratum/util/host_device.hpp"

namespace stratum {

STRATUM_HOST_DEVICE constexpr std::uint32_t reverse_bits32(std::uint32_t v) noexcept {
  v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
  v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
  v = ((v >> 4) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4);
  v = ((v >> 8) & 0x00ff00ffu) | ((v & 0x00ff00ffu) << 8);
  return (v >> 16) | (v << 16);
}

/// Byte swap, then reverse the bits within each byte (three mask steps); on
/// the device one `brev` instruction (the same bits).
STRATUM_HOST_DEVICE constexpr std::uint64_t reverse_bits64(std::uint64_t v) noexcept {
#if defined(__CUDA_ARCH__)
  if (!std::is_constant_evaluated()) return __brevll(v);
  v = ((v >> 32) | (v << 32));
  v = ((v >> 16) & 0x0000ffff0000ffffULL) | ((v & 0x0000ffff0000ffffULL) << 16);
  v = ((v >> 8) & 0x00ff00ff00ff00ffULL) | ((v & 0x00ff00ff00ff00ffULL) << 8);
#else
  v = __builtin_bswap64(v);
#endif
  v = ((v >> 4) & 0x0f0f0f0f0f0f0f0fULL) | ((v & 0x0f0f0f0f0f0f0f0fULL) << 4);
  v = ((v >> 2) & 0x3333333333333333ULL) | ((v & 0x3333333333333333ULL) << 2);
  v = ((v >> 1) & 0x5555555555555555ULL) | ((v & 0x5555555555555555ULL) << 1);
  return v;
}

/// std::countl_zero, std::countr_zero and std::bit_width of a 64-bit word,
/// also in device code: there libstdc++'s versions, inside a loop, compiled
/// to an endless loop (found by tests/cuda/check_ptx.py); nvcc's intrinsics
/// give the same numbers.
STRATUM_HOST_DEVICE constexpr int countl_zero64(std::uint64_t v) noexcept {
#if defined(__CUDA_ARCH__)
  if (!std::is_constant_evaluated()) return __clzll(static_cast<long long>(v));
#endif
  return std::countl_zero(v);
}
STRATUM_HOST_DEVICE constexpr int countr_zero64(std::uint64_t v) noexcept {
#if defined(__CUDA_ARCH__)
  if (!std::is_constant_evaluated()) return v == 0 ? 64 : __ffsll(static_cast<long long>(v)) - 1;
#endif
  return std::countr_zero(v);
}
STRATUM_HOST_DEVICE constexpr int bit_width64(std::uint64_t v) noexcept { return 64 - countl_zero64(v); }

}  // namespace stratum
