#pragma once
/// Point sets as every layer passes them: n points of d coordinates,
/// row-major. PointSet owns its buffer (the registry fills it; numpy and
/// the writers take it without a copy); PointView borrows a caller's (a
/// file read, a Python array) for the measures.
#include <cstddef>
#include <memory>

namespace stratum {

struct PointSet {
  std::size_t n = 0;
  std::size_t d = 0;
  std::unique_ptr<double[]> data;
  double operator()(std::size_t i, std::size_t j) const { return data[i * d + j]; }
};

struct PointView {
  const double* data = nullptr;
  std::size_t n = 0;
  std::size_t d = 0;
  double operator()(std::size_t i, std::size_t j) const { return data[i * d + j]; }
};

}  // namespace stratum
