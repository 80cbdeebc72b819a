#pragma once
/// Independent uniform random points, counter-based: point i, coordinate j
/// is a pure function of (seed, i, j), so any subset can be regenerated.
#include <cstdint>

#include "stratum/util/hash.hpp"

namespace stratum {

class RandomPattern {
 public:
  explicit RandomPattern(std::uint64_t seed) : seed_(seed) {}
  template <class Real = double>
  constexpr Real sample(std::uint64_t index, unsigned dim) const noexcept {
    return uniform01<Real>(seed_, index, dim);
  }

 private:
  std::uint64_t seed_;
};

}  // namespace stratum
