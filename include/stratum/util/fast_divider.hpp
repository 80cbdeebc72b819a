#pragma once
/// Division by a divisor fixed in advance, without a hardware division: the
/// digit randomizers' bases, Faure's base, Kensler's permutation domains.
#include <cstdint>

#include "stratum/util/bits.hpp"
#include "stratum/util/host_device.hpp"

namespace stratum {

/// Exact n / d by one 64×64→128 multiplication for n < limit() (Lemire,
/// Kaser, Kurz 2019, Theorem 1 with F = 64: c = ⌈2^64 / d⌉ is exact for
/// n < 2^(64 − ⌈log2 d⌉)); a hardware division above.
class FastDivider {
 public:
  constexpr FastDivider() noexcept = default;
  STRATUM_HOST_DEVICE explicit constexpr FastDivider(std::uint64_t divisor) noexcept
      : divisor_(divisor),
        magic_(~std::uint64_t{0} / divisor + 1),
        limit_(std::uint64_t{1} << (64 - bit_width64(divisor - 1))) {}
  STRATUM_HOST_DEVICE constexpr std::uint64_t divisor() const noexcept { return divisor_; }
  STRATUM_HOST_DEVICE constexpr std::uint64_t limit() const noexcept { return limit_; }
  STRATUM_HOST_DEVICE constexpr std::uint64_t quotient(std::uint64_t n) const noexcept {
    if (n < limit_) return static_cast<std::uint64_t>((static_cast<unsigned __int128>(n) * magic_) >> 64);
    return n / divisor_;
  }

 private:
  std::uint64_t divisor_ = 2;
  std::uint64_t magic_ = std::uint64_t{1} << 63;
  std::uint64_t limit_ = std::uint64_t{1} << 63;
};

}  // namespace stratum
