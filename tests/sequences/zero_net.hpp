#pragma once
// The (0, m, 2)-net check the pixel-sampler tests share.
#include <array>
#include <bit>
#include <cstddef>
#include <vector>

namespace stratum::testing {

/// Whether the points form a (0, m, 2)-net in base 2 (n = 2^m): every
/// elementary box 2^-a × 2^-(m-a) holds exactly one point.
inline bool is_zero_net(const std::vector<std::array<double, 2>>& points) {
  const std::size_t n = points.size();
  const int m = std::countr_zero(n);
  for (int a = 0; a <= m; ++a) {
    std::vector<int> count(n, 0);
    for (const auto& p : points) {
      const auto i = static_cast<std::size_t>(p[0] * double(1u << a));
      const auto j = static_cast<std::size_t>(p[1] * double(1u << (m - a)));
      ++count[i * (std::size_t(1) << (m - a)) + j];
    }
    for (int c : count)
      if (c != 1) return false;
  }
  return true;
}

}  // namespace stratum::testing
