#pragma once
/// The first prime numbers, computed at compile time (sieve of Eratosthenes):
/// the bases of Halton and Hammersley points.
#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "stratum/util/host_device.hpp"
namespace stratum {

/// How many primes `prime(i)` provides (the 1024th prime is 8161).
inline constexpr std::size_t prime_count = 1024;

namespace detail {
constexpr std::array<std::uint32_t, prime_count> make_primes() {
  std::array<std::uint32_t, prime_count> primes{};
  constexpr std::uint32_t limit = 8200;
  std::array<bool, limit> composite{};
  std::size_t count = 0;
  for (std::uint32_t i = 2; i < limit && count < prime_count; ++i) {
    if (composite[i]) continue;
    primes[count++] = i;
    for (std::uint32_t j = i * i; j < limit; j += i) composite[j] = true;
  }
  return primes;
}
inline constexpr std::array<std::uint32_t, prime_count> primes = make_primes();
#if defined(__CUDACC__)
STRATUM_DEVICE_TABLE std::array<std::uint32_t, prime_count> device_primes = make_primes();
#endif
}  // namespace detail

/// The i-th prime, counting from 0: prime(0) = 2, prime(1) = 3, ...
/// Device code reads the device copy (compile-time evaluation recomputes).
STRATUM_HOST_DEVICE constexpr std::uint32_t prime(std::size_t i) noexcept {
#if defined(__CUDA_ARCH__)
  if (std::is_constant_evaluated()) return detail::make_primes()[i];
  return detail::device_primes[i];
#else
  return detail::primes[i];
#endif
}

}  // namespace stratum
