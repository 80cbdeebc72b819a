#include "stratum/analysis/stratification.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "stratum/util/error.hpp"

namespace stratum::analysis {
namespace {

/// Most point visits (splits × N × s) net_t_value will do: a few seconds.
constexpr double max_work = 1e10;

bool is_power_of_two(std::uint64_t v) { return v != 0 && (v & (v - 1)) == 0; }

/// m with N = base^m; throws if N is not a power of base.
unsigned exponent_of(std::size_t n, std::uint64_t base) {
  require(base >= 2 && base <= (1u << 16), "base", base, "must be an integer in [2, 65536]");
  unsigned m = 0;
  std::uint64_t power = 1;
  while (power < n) {
    power *= base;
    ++m;
  }
  require(power == n, "n", n,
          "a (t, m, s)-net in base " + std::to_string(base) + " has N = " + std::to_string(base) + "^m points (e.g. " +
              std::to_string(power / base) + " or " + std::to_string(power) + ")");
  return m;
}

/// floor(x·scale) clamped to [0, scale − 1]; nudged up by a relative 1e-12
/// when scale is not a power of 2 (see the header).
std::uint64_t interval_index(double x, std::uint64_t scale, bool nudge) {
  double v = x * static_cast<double>(scale);
  if (nudge) v *= 1.0 + 1e-12;
  const double cell = std::floor(v);
  if (!(cell > 0)) return 0;
  return std::min(static_cast<std::uint64_t>(cell), scale - 1);
}

double binomial(unsigned n, unsigned k) {
  double value = 1;
  for (unsigned i = 1; i <= k; ++i) value = value * (n - k + i) / i;
  return value;
}

/// Calls visit(digits) for every split of `total` digits over `parts` axes
/// (every composition with zero parts allowed), in lexicographic order;
/// stops when visit returns false and then returns false.
template <class Visit>
bool for_each_split(unsigned total, std::size_t parts, Visit&& visit) {
  std::vector<unsigned> digits(parts, 0);
  digits[parts - 1] = total;
  while (true) {
    if (!visit(digits)) return false;
    // Next composition: move one unit from the last non-zero part before the
    // end (carrying the tail) — standard odometer over compositions.
    std::size_t j = parts - 1;
    while (j > 0 && digits[j] == 0) --j;
    if (j == 0) return true;  // all digits in the first part: done
    const unsigned tail = digits[j];
    digits[j] = 0;
    digits[j - 1] += 1;
    digits[parts - 1] = tail - 1;
  }
}

struct NetInput {
  unsigned m;
  std::vector<std::uint64_t> powers;  // base^0..base^m
};

NetInput prepare(const PointView& points, std::uint64_t base) {
  check_unit_cube(points);
  NetInput input;
  input.m = exponent_of(points.n, base);
  input.powers.assign(input.m + 1, 1);
  for (unsigned k = 1; k <= input.m; ++k) input.powers[k] = input.powers[k - 1] * base;
  const double work = binomial(input.m + static_cast<unsigned>(points.d), static_cast<unsigned>(points.d)) *
                      static_cast<double>(points.n) * static_cast<double>(points.d);
  require(work <= max_work, "n", points.n,
          "the t-value check of " + std::to_string(points.n) + " points in d = " + std::to_string(points.d) +
              " would visit " + to_message_string(work) +
              " point-intervals (at most 1e10 allowed): use fewer points or dimensions");
  return input;
}

/// Smallest t, scanning t = m−1, m−2, ... down while the set is still a net.
template <class IsNet>
NetQuality smallest_t(unsigned m, IsNet&& is_net) {
  NetQuality quality{m, m};
  for (unsigned t = m; t-- > 0;) {
    if (!is_net(t)) break;
    quality.t = t;
  }
  return quality;
}

}  // namespace

NetQuality net_t_value(const PointView& points, std::uint64_t base) {
  const NetInput input = prepare(points, base);
  const unsigned m = input.m;
  const bool nudge = !is_power_of_two(base);
  // Every coordinate's interval index at the finest level b^m; coarser levels
  // are its integer quotients (floor(x b^d) = floor(floor(x b^m) / b^(m−d))).
  std::vector<std::uint64_t> finest(points.n * points.d);
  for (std::size_t i = 0; i < points.n; ++i)
    for (std::size_t j = 0; j < points.d; ++j)
      finest[i * points.d + j] = interval_index(points(i, j), input.powers[m], nudge);
  std::vector<std::uint32_t> counts;
  auto is_net = [&](unsigned t) {
    const std::uint64_t capacity = input.powers[t];
    counts.assign(input.powers[m - t], 0);
    return for_each_split(m - t, points.d, [&](const std::vector<unsigned>& digits) {
      std::fill(counts.begin(), counts.end(), 0u);
      for (std::size_t i = 0; i < points.n; ++i) {
        std::uint64_t cell = 0;
        for (std::size_t j = 0; j < points.d; ++j)
          cell = cell * input.powers[digits[j]] + finest[i * points.d + j] / input.powers[m - digits[j]];
        if (++counts[cell] > capacity) return false;
      }
      return true;
    });
  };
  return smallest_t(m, is_net);
}

NetQuality net_t_value_reference(const PointView& points, std::uint64_t base) {
  const NetInput input = prepare(points, base);
  const unsigned m = input.m;
  const bool nudge = !is_power_of_two(base);
  const double slack = nudge ? 1e-12 : 0.0;
  auto is_net = [&](unsigned t) {
    return for_each_split(m - t, points.d, [&](const std::vector<unsigned>& digits) {
      // Enumerate every interval of this split as an odometer over a_j.
      std::vector<std::uint64_t> a(points.d, 0);
      while (true) {
        std::uint64_t inside = 0;
        for (std::size_t i = 0; i < points.n; ++i) {
          bool in = true;
          for (std::size_t j = 0; j < points.d && in; ++j) {
            const double scaled = points(i, j) * static_cast<double>(input.powers[digits[j]]) * (1.0 + slack);
            const bool last = a[j] + 1 == input.powers[digits[j]];
            in = scaled >= static_cast<double>(a[j]) && (scaled < static_cast<double>(a[j] + 1) || last);
          }
          inside += in;
        }
        if (inside != input.powers[t]) return false;
        std::size_t j = 0;
        while (j < points.d && ++a[j] == input.powers[digits[j]]) a[j++] = 0;
        if (j == points.d) return true;
      }
    });
  };
  return smallest_t(m, is_net);
}

LatinCheck latin_check(const PointView& points) {
  check_unit_cube(points);
  const bool nudge = !is_power_of_two(points.n);
  LatinCheck check;
  std::vector<std::size_t> counts(points.n);
  for (std::size_t j = 0; j < points.d; ++j) {
    std::fill(counts.begin(), counts.end(), 0);
    for (std::size_t i = 0; i < points.n; ++i) ++counts[interval_index(points(i, j), points.n, nudge)];
    for (std::size_t c : counts) {
      if (c > check.worst_count) {
        check.worst_count = c;
        check.worst_axis = j;
      }
      check.empty_strata += c == 0;
    }
  }
  check.latin = check.worst_count == 1;
  return check;
}

}  // namespace stratum::analysis
