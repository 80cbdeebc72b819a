// The registry entries of the L2 discrepancies: l2-star, cd, wd, md. Each
// reports the discrepancy itself (the root of the L2 norm's square) as its
// value and the square in extras["squared"]: scipy.stats.qmc.discrepancy
// returns the square for CD, WD and MD and the root for L2-star, which
// stratum.qmc.discrepancy reproduces (docs/discrepancy.md).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "measure_families.hpp"
#include "stratum/analysis/l2_discrepancy.hpp"
#include "stratum/util/error.hpp"

namespace stratum::analysis::measure_families {
namespace {

L2Algorithm algorithm_of(const MeasureRequest& request) {
  const std::string& text = request.values.text("algorithm");
  if (text == "warnock") return L2Algorithm::pairwise;
  if (text == "fast") return L2Algorithm::fast;
  return L2Algorithm::automatic;
}

MeasureResult l2_result(L2Kind kind, const PointView& points, const MeasureRequest& request) {
  L2Options options;
  options.threads = request.threads;
  if (kind == L2Kind::star) options.algorithm = algorithm_of(request);
  // Warnock's terms are products of d factors at most 1 (3^-d the first): past
  // d = 644 they underflow and the result would read 0, silently wrong.
  if (kind == L2Kind::star && std::pow(3.0, -double(points.d)) < std::numeric_limits<double>::min())
    throw invalid_argument("d", std::to_string(points.d),
                           "l2-star's terms (3^-d and products of d factors below 1) underflow double precision "
                           "past d = 644: the result would read 0");
  const double squared = l2_discrepancy_squared(kind, points, options);
  MeasureResult result;
  result.kind = "exact";
  result.value = std::sqrt(std::max(squared, 0.0));  // rounding can leave −1e-17 for a perfect set
  result.extras["squared"] = squared;
  return result;
}

MeasureInfo l2_measure(std::string name, std::string description, L2Kind kind) {
  MeasureInfo info;
  info.name = std::move(name);
  info.description = std::move(description);
  info.compute = [kind](const PointView& points, const MeasureRequest& request) {
    return l2_result(kind, points, request);
  };
  info.working_bytes = [kind](std::size_t n, std::size_t d, const MeasureRequest& request) {
    L2Options options;
    if (kind == L2Kind::star) options.algorithm = algorithm_of(request);
    return l2_working_bytes(kind, n, d, options);
  };
  return info;
}

}  // namespace

std::vector<MeasureInfo> l2() {
  MeasureInfo star = l2_measure(
      "l2-star",
      "L2-star discrepancy: L2 norm of the local discrepancy over anchored boxes [0,x), by Warnock's formula (Warnock "
      "1972), O(N log N) for d = 2 and O(N log^2 N) for d = 3 (Heinrich 1996); value = D, extras squared = D^2 "
      "(scipy's "
      "'L2-star' returns D)",
      L2Kind::star);
  star.params = {params::choice("algorithm", "auto (fast for d <= 3), warnock (O(d N^2)) or fast (d <= 3)", "auto",
                                {"auto", "warnock", "fast"})};
  star.validate = [](const PointView& points, const MeasureRequest& request) {
    if (algorithm_of(request) == L2Algorithm::fast && points.d > 3)
      throw invalid_argument("algorithm", "fast",
                             "the fast L2-star algorithm covers d <= 3 (d = " + std::to_string(points.d) +
                                 "); use algorithm=warnock or auto");
  };
  return {
      star,
      l2_measure("cd",
                 "centered L2 discrepancy (Hickernell 1998), scipy's 'CD' definition; value = CD, extras squared = "
                 "CD^2 (what scipy returns)",
                 L2Kind::centered),
      l2_measure("wd",
                 "wrap-around L2 discrepancy (Hickernell 1998), scipy's 'WD' definition; value = WD, extras squared = "
                 "WD^2 (what scipy returns)",
                 L2Kind::wrap_around),
      l2_measure("md",
                 "mixture L2 discrepancy (Zhou, Fang, Ning 2013), scipy's 'MD' definition; value = MD, extras squared "
                 "= MD^2 (what scipy returns)",
                 L2Kind::mixture),
  };
}

}  // namespace stratum::analysis::measure_families
