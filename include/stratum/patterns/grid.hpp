#pragma once
/// The regular grid: the centres of the cells of an n_0 × … × n_{d-1}
/// subdivision of [0, 1)^d. The product rule of numerical quadrature (the
/// midpoint rule in every dimension); its error falls as N^(-2/d) for smooth
/// integrands, the N^(-1/d) "curse of dimensionality" of lecture §6 for
/// discontinuous ones, and its regular spacing aliases (Cook 1986,
/// "Stochastic sampling in computer graphics"). Index-addressable: cell i has
/// digit (i / (n_0 ⋯ n_{j-1})) mod n_j in dimension j.
#include <cstdint>
#include <utility>

#include "stratum/patterns/strata.hpp"

namespace stratum {

class Grid {
 public:
  explicit Grid(StrataShape shape) : shape_(std::move(shape)) {}

  const StrataShape& shape() const noexcept { return shape_; }
  std::uint64_t count() const noexcept { return shape_.count(); }
  unsigned dimensions() const noexcept { return shape_.dimensions(); }

  /// (cell + 1/2) / n_dim, correctly rounded.
  template <class Real = double>
  Real sample(std::uint64_t index, unsigned dim) const noexcept {
    return cell_coordinate<Real>(shape_.cell(index, dim), 0.5, shape_.strata(dim));
  }

 private:
  StrataShape shape_;
};

}  // namespace stratum
