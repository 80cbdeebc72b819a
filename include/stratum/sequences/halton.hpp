#pragma once
/// Halton points (φ2(i), φ3(i), φ5(i), …): the radical inverse in the
/// d-th prime base for dimension d (Halton 1960). Sequential, with star
/// discrepancy O(log^d N / N).
#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "stratum/sequences/radical_inverse.hpp"
#include "stratum/util/primes.hpp"

namespace stratum {

namespace detail {
/// radical_inverse_reciprocal of every prime base, computed at compile time.
constexpr std::array<std::uint64_t, prime_count> make_prime_reciprocals() {
  const std::array<std::uint32_t, prime_count> primes = make_primes();
  std::array<std::uint64_t, prime_count> table{};
  for (std::size_t i = 0; i < prime_count; ++i) table[i] = radical_inverse_reciprocal(primes[i]);
  return table;
}
inline constexpr std::array<std::uint64_t, prime_count> prime_reciprocals = make_prime_reciprocals();
#if defined(__CUDACC__)
STRATUM_DEVICE_TABLE std::array<std::uint64_t, prime_count> device_prime_reciprocals = make_prime_reciprocals();
#endif

/// radical_inverse_reciprocal(prime(i)), from the table of the side that runs.
STRATUM_HOST_DEVICE constexpr std::uint64_t prime_reciprocal(std::size_t i) noexcept {
#if defined(__CUDA_ARCH__)
  if (std::is_constant_evaluated()) return radical_inverse_reciprocal(prime(i));
  return device_prime_reciprocals[i];
#else
  return prime_reciprocals[i];
#endif
}
}  // namespace detail

class Halton {
 public:
  /// Highest dimension count: one prime base per dimension.
  static constexpr unsigned max_dimensions = static_cast<unsigned>(prime_count);

  explicit Halton(unsigned dimensions) : dimensions_(dimensions) {
    require(dimensions >= 1 && dimensions <= max_dimensions, "d", dimensions,
            "Halton supports 1 to 1024 dimensions (one prime base each)");
  }
  STRATUM_HOST_DEVICE unsigned dimensions() const noexcept { return dimensions_; }
  /// Base of dimension `dim` (the dim-th prime).
  STRATUM_HOST_DEVICE static constexpr std::uint32_t base(unsigned dim) noexcept { return prime(dim); }

  template <class Real = double>
  STRATUM_HOST_DEVICE constexpr Real sample(std::uint64_t index, unsigned dim) const noexcept {
    return to_unit<Real>(radical_inverse(base(dim), index, detail::prime_reciprocal(dim)));
  }

 private:
  unsigned dimensions_;
};

/// Hammersley points (i/N, φ2(i), φ3(i), φ5(i), …) for a fixed N
/// (Hammersley 1964): star discrepancy O(log^(d-1) N / N), one log better
/// than Halton, at the price of fixing N in advance.
class Hammersley {
 public:
  static constexpr unsigned max_dimensions = static_cast<unsigned>(prime_count) + 1;

  Hammersley(std::uint64_t count, unsigned dimensions) : count_(count), dimensions_(dimensions) {
    require(count >= 1, "n", count, "Hammersley needs at least one point");
    require(dimensions >= 1 && dimensions <= max_dimensions, "d", dimensions,
            "Hammersley supports 1 to 1025 dimensions");
  }
  STRATUM_HOST_DEVICE std::uint64_t count() const noexcept { return count_; }
  STRATUM_HOST_DEVICE unsigned dimensions() const noexcept { return dimensions_; }
  /// Base of dimension dim ≥ 1 (dimension 0 is i/N).
  STRATUM_HOST_DEVICE static constexpr std::uint32_t base(unsigned dim) noexcept { return prime(dim - 1); }

  template <class Real = double>
  STRATUM_HOST_DEVICE constexpr Real sample(std::uint64_t index, unsigned dim) const noexcept {
    if (dim == 0) return to_unit<Real>(static_cast<double>(index) / static_cast<double>(count_));
    return to_unit<Real>(radical_inverse(base(dim), index, detail::prime_reciprocal(dim - 1)));
  }

 private:
  std::uint64_t count_;
  unsigned dimensions_;
};

}  // namespace stratum
