#pragma once
/// Jittered (stratified) sampling: one uniform point in each cell of an
/// n_0 × … × n_{d-1} grid (Cook, Porter, Carpenter 1984, "Distributed ray
/// tracing"; Cook 1986, "Stochastic sampling in computer graphics"). Lecture
/// §4: with the strata as the cells, the variance (1/N²) Σ V[F_i] never
/// exceeds that of independent points, and for a pixel crossed by an edge it
/// falls as N^-1.5 instead of N^-1. Index-addressable: point i lies in grid
/// cell i (as Grid) at an offset drawn from (seed, i, dim).
#include <cstdint>
#include <utility>

#include "stratum/patterns/strata.hpp"

namespace stratum {

class Jittered {
 public:
  Jittered(StrataShape shape, std::uint64_t seed) : shape_(std::move(shape)), key_(key_of(seed)) {}

  /// The key of a seed's offsets: the offset of point i in dimension j is
  /// uniform01(key_of(seed), i, j).
  STRATUM_HOST_DEVICE static constexpr std::uint64_t key_of(std::uint64_t seed) noexcept {
    return hash64(seed, 0x4a49545445524544ULL);
  }

  const StrataShape& shape() const noexcept { return shape_; }
  std::uint64_t count() const noexcept { return shape_.count(); }
  unsigned dimensions() const noexcept { return shape_.dimensions(); }

  template <class Real = double>
  Real sample(std::uint64_t index, unsigned dim) const noexcept {
    return cell_coordinate<Real>(shape_.cell(index, dim), uniform01<double>(key_, index, dim), shape_.strata(dim));
  }

 private:
  StrataShape shape_;
  std::uint64_t key_;
};

}  // namespace stratum
