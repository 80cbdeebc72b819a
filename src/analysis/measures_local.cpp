// Registry entries that say *where* and *what for* a 2D star discrepancy:
// the anchored box attaining D*_N (local_discrepancy.hpp) and the
// Koksma–Hlawka inequality checked on test functions of known Hardy–Krause
// variation (koksma_hlawka.hpp). In the registry, both reach the CLI
// (`stratum discrepancy -m star-box`) and Python (`stratum.measure`).
#include <algorithm>

#include "measure_families.hpp"
#include "stratum/analysis/koksma_hlawka.hpp"
#include "stratum/analysis/local_discrepancy.hpp"
#include "stratum/analysis/star_discrepancy.hpp"
#include "stratum/util/error.hpp"

namespace stratum::analysis::measure_families {
namespace {

/// The box sweep is O(N²) time: at 20000 points about a second.
constexpr std::size_t kMaxBoxPoints = 20000;

MeasureInfo star_box() {
  MeasureInfo info;
  info.name = "star-box";
  info.description =
      "where D* is attained in 2D: value D*, extras x, y (the box [0,x) x [0,y)), closed (1: too many points, the "
      "box's upper edges included, approached from above; 0: too few) and count (points in it); O(N^2) sweep, "
      "N <= 20000 (Niederreiter 1992, Def. 2.1; Gnewuch, Srivastav, Winzen 2009, Lemma 1.1)";
  info.min_dim = info.max_dim = 2;
  info.validate = [](const PointView& points, const MeasureRequest&) {
    require(points.n <= kMaxBoxPoints, "n", points.n, "the star-box sweep takes at most 20000 points (O(N^2))");
  };
  info.compute = [](const PointView& points, const MeasureRequest&) {
    const StarDiscrepancyBox box = star_discrepancy_box(points);
    MeasureResult result;
    result.value = box.value;
    result.extras = {
        {"x", box.x}, {"y", box.y}, {"closed", box.closed ? 1.0 : 0.0}, {"count", static_cast<double>(box.count)}};
    return result;
  };
  return info;
}

MeasureInfo koksma_hlawka() {
  MeasureInfo info;
  info.name = "koksma-hlawka";
  info.description =
      "the Koksma-Hlawka inequality |mean f(p_i) - integral f| <= V_HK(f) D* checked in 2D on test functions "
      "of closed-form Hardy-Krause variation (Niederreiter 1992, Thm. 2.11): value max_f error/bound (<= 1 when it "
      "holds), extras star (D*, exact sweep), holds (count), error:F and bound:F per function F";
  info.min_dim = info.max_dim = 2;
  info.validate = [](const PointView& points, const MeasureRequest&) {
    require(star_exact_feasible(points.n, 2), "n", points.n, "the exact 2D star discrepancy takes at most 2^18 points");
  };
  info.compute = [](const PointView& points, const MeasureRequest& request) {
    const double star = star_discrepancy_exact(points, request.threads);
    MeasureResult result;
    result.extras["star"] = star;
    double worst = 0, holds = 0;
    for (const KoksmaHlawkaCheck& check : koksma_hlawka_checks(points, star)) {
      worst = std::max(worst, check.bound > 0 ? check.error / check.bound : (check.error > 0 ? 1e300 : 0.0));
      holds += check.holds ? 1 : 0;
      result.extras["error:" + check.function] = check.error;
      result.extras["bound:" + check.function] = check.bound;
    }
    result.value = worst;
    result.extras["holds"] = holds;
    return result;
  };
  return info;
}

}  // namespace

std::vector<MeasureInfo> local() { return {star_box(), koksma_hlawka()}; }

}  // namespace stratum::analysis::measure_families
