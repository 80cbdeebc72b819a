#pragma once
// χ² goodness-of-fit of a warp against its density, shared by the warp tests
// (tests/warps) and the renderer's sampling tests (tests/render), after
// Mitsuba 3's `chi2` test and Nori's warptest.
//
// API
//   using SampleFn = std::function<void(const double* u, double* out)>;  // u: input_dim numbers in [0,1)
//   using PdfFn    = std::function<double(const double* p)>;             // density at a point of the domain
//   Domain::interval(lo, hi, bins)               1D points (out[0]); pdf per unit length
//   Domain::box(x0, x1, y0, y1, nx, ny)          planar points (out[0..1]); pdf per unit area; grid bins
//   Domain::disk(radius, n_radial, n_angular)    planar points in a centred disk; equal-area bins in (r², φ)
//   Domain::directions(z_min, z_max, n_z, n_phi) unit vectors (out[0..2]); pdf per steradian;
//                                                equal-solid-angle bins in (z = cos θ, φ)
//   Chi2Result chi2_test(sample, pdf, domain, Chi2Options{samples, seed, input_dim, subdivisions})
//       -> {statistic, dof, p_value, table}
//   expect_chi2(result, what)                     the family's check: p > chi2_alpha(), once per gtest,
//                                                 only in a test suite whose name ends in "Chi2"
//   Chi2Fixture<Base>                             fixture for such suites: fails a test that never called
//                                                 expect_chi2 (TEST_F, or TEST_P with Base = TestWithParam<P>)
//   chi2_param_name(name)                         a case's name as a gtest parameter name ("cone -0.3" -> cone_m0_3)
//   double sidak_alpha(family_alpha, tests)       per-test level for `tests` χ² tests at family level
//   int chi2_tests_in_suite()                     T: registered tests in suites named *Chi2 (computed)
//   chi2_alpha()                                  sidak_alpha(0.01, T)
//   std::vector<int> stratum_hits(sample, n0, n1, seed, cell_of, cells)
//       maps one jittered point per cell of an n0 × n1 grid of the unit square and counts the images
//       per image cell (cell_of: point -> index in [0, cells), -1 for none).
//
// Method. N points are drawn from `sample` with stratum's counter-based uniforms
// u_ij = uniform01(seed, i, j) and binned. Samples that fall in no bin (outside
// the range, or off an unbounded interval) go to one "outside" cell whose
// expected count is N (1 − Σ bin masses). Each bin's expected count is N times
// the integral of the pdf over the bin, computed by 3-point Gauss–Legendre on
// a fine subgrid of `subdivisions` × `subdivisions` panels per bin (not
// adaptive: its cost is fixed and it does not stall on indicator-like densities;
// its error is O(h⁶) for smooth densities and a fraction of one sub-panel along
// a discontinuity; an open rule, so a jump on a bin edge costs nothing). Cells are sorted by expected count and those
// below min_expected = 5 are pooled into one cell, as Mitsuba's ChiSquareTest does; a cell with expected count 0 but
// observations makes the statistic infinite. A density with a jump inside the bins (an indicator such as a disk or a
// triangle binned on its bounding box) needs subdivisions = 32: at the default
// 8 the rim cells' expected counts may be off by ~1.5%, which biases p low at
// 2·10⁵ samples (measured with Simpson's rule, the concentric disk and a 16 × 16 box grid).
// dof = (cells after pooling) − 1; p = 1 − F_χ²(statistic; dof) with Boost.Math.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numbers>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <boost/math/distributions/chi_squared.hpp>
#include <gtest/gtest.h>

#include "stratum/util/hash.hpp"

namespace stratum::testing {

using SampleFn = std::function<void(const double* u, double* out)>;
using PdfFn = std::function<double(const double* p)>;

/// How samples are binned: two bin coordinates (s, t) with ranges [s0, s1) ×
/// [t0, t1), a measure factor (dA or dω per ds dt) and the point for (s, t).
struct Domain {
  enum class Kind { interval, box, disk, directions };
  Kind kind = Kind::box;
  double s0 = 0, s1 = 1, t0 = 0, t1 = 1;
  int s_bins = 1, t_bins = 1;

  static Domain interval(double lo, double hi, int bins) { return {Kind::interval, lo, hi, 0, 1, bins, 1}; }
  static Domain box(double x0, double x1, double y0, double y1, int nx, int ny) {
    return {Kind::box, x0, x1, y0, y1, nx, ny};
  }
  /// s = r² ∈ [0, radius²), t = φ ∈ [0, 2π): dA = ½ ds dt, so equal (s, t) cells have equal area.
  static Domain disk(double radius, int n_radial, int n_angular) {
    return {Kind::disk, 0, radius * radius, 0, 2 * std::numbers::pi, n_radial, n_angular};
  }
  /// s = z = cos θ, t = φ ∈ [0, 2π): dω = ds dt (Archimedes), equal cells have equal solid angle.
  static Domain directions(double z_min, double z_max, int n_z, int n_phi) {
    return {Kind::directions, z_min, z_max, 0, 2 * std::numbers::pi, n_z, n_phi};
  }

  unsigned point_dim() const { return kind == Kind::interval ? 1 : kind == Kind::directions ? 3 : 2; }
  double measure_factor() const { return kind == Kind::disk ? 0.5 : 1.0; }

  /// The point of the domain at bin coordinates (s, t).
  void point(double s, double t, double* p) const {
    switch (kind) {
      case Kind::interval:
        p[0] = s;
        break;
      case Kind::box:
        p[0] = s, p[1] = t;
        break;
      case Kind::disk: {
        const double r = std::sqrt(std::max(s, 0.0));
        p[0] = r * std::cos(t), p[1] = r * std::sin(t);
        break;
      }
      case Kind::directions: {
        const double sin_theta = std::sqrt(std::max(0.0, 1 - s * s));
        p[0] = sin_theta * std::cos(t), p[1] = sin_theta * std::sin(t), p[2] = s;
        break;
      }
    }
  }
  /// The bin index of a point, or -1 when it lies in no bin.
  long bin_of(const double* p) const {
    double s = 0, t = 0;
    switch (kind) {
      case Kind::interval:
        s = p[0], t = 0.5 * (t0 + t1);
        break;
      case Kind::box:
        s = p[0], t = p[1];
        break;
      case Kind::disk:
        s = p[0] * p[0] + p[1] * p[1], t = angle(p[1], p[0]);
        break;
      case Kind::directions:
        s = p[2], t = angle(p[1], p[0]);
        break;
    }
    if (!(s >= s0 && s <= s1 && t >= t0 && t <= t1)) return -1;
    const auto i = std::min<long>(s_bins - 1, static_cast<long>((s - s0) / (s1 - s0) * s_bins));
    const auto j = std::min<long>(t_bins - 1, static_cast<long>((t - t0) / (t1 - t0) * t_bins));
    return j * s_bins + i;
  }

 private:
  static double angle(double y, double x) {
    const double phi = std::atan2(y, x);
    return phi < 0 ? phi + 2 * std::numbers::pi : phi;
  }
};

struct Chi2Options {
  std::uint64_t samples = 200000;
  std::uint64_t seed = 1;
  unsigned input_dim = 2;
  int subdivisions = 8;  ///< Gauss–Legendre sub-panels per bin and axis
  double min_expected = 5;
};

struct Chi2Result {
  double statistic = 0;
  int dof = 0;
  double p_value = 0;
  std::string table;  ///< the cells contributing most to the statistic, for failure messages
};

/// Šidák-corrected per-test level: 1 − (1 − family_alpha)^(1/tests).
inline double sidak_alpha(double family_alpha, int tests) { return 1.0 - std::pow(1.0 - family_alpha, 1.0 / tests); }

/// The χ² family. Every gtest in a test suite whose name ends in "Chi2" is one
/// χ² test of a correct sampler (TEST_P instantiations count each parameter:
/// their suite is "Prefix/NameChi2"). T is counted from gtest's registry, which
/// holds every test of the binary whatever --gtest_filter selects, so a ctest
/// process running one test computes the same T as a full run. expect_chi2
/// refuses to run outside such a suite or twice in one gtest, so the family
/// can never hold more χ² tests than T. Tests that check a wrong sampler is
/// rejected (p < 1e-12) are not members: their suites do not end in "Chi2".
inline bool is_chi2_suite(std::string_view suite_name) { return suite_name.ends_with("Chi2"); }

/// T: the number of registered tests in suites whose name ends in "Chi2".
inline int chi2_tests_in_suite() {
  const ::testing::UnitTest& unit = *::testing::UnitTest::GetInstance();
  int tests = 0;
  for (int i = 0; i < unit.total_test_suite_count(); ++i) {
    const ::testing::TestSuite& suite = *unit.GetTestSuite(i);
    if (is_chi2_suite(suite.name())) tests += suite.total_test_count();
  }
  return tests;
}

/// The level every χ² test of the family uses: Šidák at family α = 0.01 over
/// the computed T, so the whole binary raises a false alarm with probability
/// at most 1%; per test about 0.01/T (T = 41 today with the renderer, 2.45e-4;
/// 31 without it; printed by WarpChi2Family.CountIsComputedFromTheRegisteredTests).
inline double chi2_alpha() { return sidak_alpha(0.01, chi2_tests_in_suite()); }

/// The property a family member records its p-value under (visible in
/// --gtest_output=xml); its presence marks that the test has had its χ² check.
inline constexpr const char* chi2_property = "chi2_p_value";

inline bool chi2_recorded(const ::testing::TestInfo& test) {
  const ::testing::TestResult& result = *test.result();
  for (int i = 0; i < result.test_property_count(); ++i)
    if (std::string_view(result.GetTestProperty(i).key()) == chi2_property) return true;
  return false;
}

/// The family's one check: p > chi2_alpha(). Fails the test instead when it
/// runs outside a *Chi2 suite or a second time in the same gtest, either of
/// which would make the family hold more χ² tests than T counts.
inline void expect_chi2(const Chi2Result& result, const std::string& what = {}) {
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  if (test == nullptr) {
    ADD_FAILURE() << "expect_chi2 outside a running test";
    return;
  }
  const std::string name = std::string(test->test_suite_name()) + "." + test->name();
  if (!is_chi2_suite(test->test_suite_name())) {
    ADD_FAILURE() << "expect_chi2 in " << name << ": a χ² test of the family must live in a test suite whose "
                  << "name ends in \"Chi2\", or the Šidák count T (tests/warps/chi2.hpp) misses it";
    return;
  }
  if (chi2_recorded(*test)) {
    ADD_FAILURE() << "expect_chi2 called twice in " << name << " (" << what << "): one χ² test per gtest, "
                  << "or the Šidák count T (tests/warps/chi2.hpp) is too small; make each case its own TEST_P";
    return;
  }
  ::testing::Test::RecordProperty(chi2_property, std::to_string(result.p_value));
  const int tests = chi2_tests_in_suite();
  EXPECT_GT(result.p_value, chi2_alpha())
      << what << (what.empty() ? "" : "\n") << "level: Šidák, family α = 0.01 over T = " << tests << " χ² tests\n"
      << result.table;
}

/// Fixture of a *Chi2 suite: a test that ends without its χ² check fails.
template <class Base = ::testing::Test>
class Chi2Fixture : public Base {
 protected:
  void TearDown() override {
    const ::testing::TestInfo& test = *::testing::UnitTest::GetInstance()->current_test_info();
    if (!this->HasFatalFailure() && !this->IsSkipped() && !chi2_recorded(test))
      ADD_FAILURE() << test.test_suite_name() << "." << test.name() << " is in a *Chi2 suite but made no χ² check "
                    << "(expect_chi2): it is counted in T for nothing, or its check was lost";
  }
};

/// A case's display name as a gtest parameter name: letters and digits kept,
/// a minus sign before a number as "m", anything else one "_".
inline std::string chi2_param_name(std::string_view name) {
  std::string out;
  for (std::size_t i = 0; i < name.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(name[i]);
    const bool starts_number = c == '-' && i + 1 < name.size() &&
                               std::isdigit(static_cast<unsigned char>(name[i + 1])) &&
                               (i == 0 || !std::isalnum(static_cast<unsigned char>(name[i - 1])));
    if (std::isalnum(c) && c < 128) {
      out += static_cast<char>(c);
    } else if (starts_number) {
      if (!out.empty() && out.back() != '_') out += '_';
      out += 'm';
    } else if (!out.empty() && out.back() != '_') {
      out += '_';
    }
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out;
}

/// Integral of pdf × measure over bin (i, j): 3-point Gauss–Legendre on each
/// of `subdivisions` × `subdivisions` sub-panels. An open rule: it never
/// evaluates the pdf on a bin's edge, so a density that jumps exactly there
/// (a hemisphere's rim at z = 0, a cone's cap) gives no mass to the wrong side.
inline double bin_mass(const PdfFn& pdf, const Domain& domain, long i, long j, int subdivisions) {
  const double ds = (domain.s1 - domain.s0) / domain.s_bins, dt = (domain.t1 - domain.t0) / domain.t_bins;
  const double sa = domain.s0 + ds * static_cast<double>(i), ta = domain.t0 + dt * static_cast<double>(j);
  const bool one_d = domain.kind == Domain::Kind::interval;
  // Nodes and weights of Gauss–Legendre on [0, 1].
  const double offset = std::sqrt(0.15);
  const double node[3] = {0.5 - offset, 0.5, 0.5 + offset}, weight[3] = {5.0 / 18, 8.0 / 18, 5.0 / 18};
  const double hs = ds / subdivisions, ht = one_d ? 1.0 : dt / subdivisions;
  double p[3], sum = 0;
  for (int b = 0; b < (one_d ? 1 : subdivisions); ++b)
    for (int kb = 0; kb < (one_d ? 1 : 3); ++kb) {
      const double t = one_d ? 0.5 * (domain.t0 + domain.t1) : ta + ht * (b + node[kb]);
      const double wt = one_d ? 1.0 : weight[kb];
      for (int a = 0; a < subdivisions; ++a)
        for (int ka = 0; ka < 3; ++ka) {
          domain.point(sa + hs * (a + node[ka]), t, p);
          sum += weight[ka] * wt * pdf(p);
        }
    }
  return sum * hs * ht * domain.measure_factor();
}

inline Chi2Result chi2_test(const SampleFn& sample, const PdfFn& pdf, const Domain& domain,
                            const Chi2Options& options = {}) {
  const long bins = static_cast<long>(domain.s_bins) * domain.t_bins;
  std::vector<double> observed(bins + 1, 0.0), expected(bins + 1, 0.0);  // last: outside
  double u[2], p[3];
  for (std::uint64_t i = 0; i < options.samples; ++i) {
    for (unsigned j = 0; j < options.input_dim; ++j) u[j] = uniform01(options.seed, i, j);
    sample(u, p);
    const long bin = domain.bin_of(p);
    observed[bin < 0 ? bins : bin] += 1;
  }
  const auto n = static_cast<double>(options.samples);
  double inside = 0;
  for (long b = 0; b < bins; ++b) {
    expected[b] = n * bin_mass(pdf, domain, b % domain.s_bins, b / domain.s_bins, options.subdivisions);
    inside += expected[b];
  }
  expected[bins] = std::max(0.0, n - inside);

  std::vector<long> order(bins + 1);
  for (long b = 0; b <= bins; ++b) order[b] = b;
  std::sort(order.begin(), order.end(), [&](long a, long b) { return expected[a] < expected[b]; });
  Chi2Result result;
  std::vector<std::pair<double, long>> contributions;
  double pooled_observed = 0, pooled_expected = 0;
  int pooled_cells = 0;
  for (long b : order) {
    if (expected[b] == 0 && observed[b] > 0) result.statistic = INFINITY;
    if (expected[b] < options.min_expected || (pooled_expected > 0 && pooled_expected < options.min_expected)) {
      pooled_observed += observed[b], pooled_expected += expected[b], ++pooled_cells;
    } else {
      const double term = (observed[b] - expected[b]) * (observed[b] - expected[b]) / expected[b];
      result.statistic += term, ++result.dof;
      contributions.push_back({term, b});
    }
  }
  if (pooled_expected > 0) {
    result.statistic += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) / pooled_expected;
    ++result.dof;
  } else if (pooled_observed > 0) {
    result.statistic = INFINITY;
  }
  result.dof -= 1;
  if (result.dof < 1 || !std::isfinite(result.statistic)) {
    result.p_value = 0;
  } else {
    const boost::math::chi_squared distribution(result.dof);
    result.p_value = boost::math::cdf(boost::math::complement(distribution, result.statistic));
  }

  std::ostringstream table;
  table << "chi2 = " << result.statistic << ", dof = " << result.dof << ", p = " << result.p_value
        << ", samples = " << options.samples << ", outside: observed " << observed[bins] << " expected "
        << expected[bins] << ", pooled " << pooled_cells << " cells: observed " << pooled_observed << " expected "
        << pooled_expected << "\nlargest terms (s-bin, t-bin: observed, expected, term):\n";
  std::sort(contributions.rbegin(), contributions.rend());
  for (std::size_t k = 0; k < std::min<std::size_t>(10, contributions.size()); ++k) {
    const long b = contributions[k].second;
    table << "  (" << b % domain.s_bins << ", " << b / domain.s_bins << "): " << observed[b] << ", " << expected[b]
          << ", " << contributions[k].first << "\n";
  }
  result.table = table.str();
  return result;
}

/// One jittered point in each cell of an n0 × n1 grid of the unit square,
/// mapped by `sample`; returns how many images land in each image cell.
inline std::vector<int> stratum_hits(const SampleFn& sample, int n0, int n1, std::uint64_t seed,
                                     const std::function<long(const double* p)>& cell_of, long cells) {
  std::vector<int> hits(cells + 1, 0);  // last: points in no cell
  double u[2], p[3];
  for (int j = 0; j < n1; ++j)
    for (int i = 0; i < n0; ++i) {
      u[0] = (i + uniform01(seed, i, j, 0)) / n0;
      u[1] = (j + uniform01(seed, i, j, 1)) / n1;
      sample(u, p);
      const long cell = cell_of(p);
      ++hits[cell < 0 || cell >= cells ? cells : cell];
    }
  return hits;
}

}  // namespace stratum::testing
