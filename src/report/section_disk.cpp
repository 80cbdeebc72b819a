/// §5 Sampling a disk: a stratified grid, and its cells' boundaries, pushed
/// through the polar map (θ = 2πu₁, r = √u₂) and Shirley's concentric map (Shirley & Chiu 1997,
/// "A low distortion map between disk and square"). Measured: how compact
/// the images of the strata stay (isoperimetric ratio P²/4πA, 1 for a
/// circle, 4/π for a square) and the variance of jittered estimates of an
/// edge integral over the disk through each map.
#include <fmt/core.h>

#include <cmath>
#include <map>
#include <numbers>

#include "sections.hpp"
#include "stratum/registry.hpp"
#include "stratum/warp_registry.hpp"

namespace stratum::report {

namespace {

struct Compactness {
  double mean = 0, max = 0;
};

/// The isoperimetric ratio of each stratum's image: its boundary (16 points
/// per edge) mapped, then the polygon's perimeter and area.
Compactness strata_compactness(const Warp& warp, int cells) {
  constexpr int per_edge = 16;
  Compactness result;
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      std::vector<double> boundary;
      const double corners[5][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
      for (int e = 0; e < 4; ++e)
        for (int s = 0; s < per_edge; ++s) {
          const double t = static_cast<double>(s) / per_edge;
          const double u = (i + corners[e][0] + t * (corners[e + 1][0] - corners[e][0])) / cells;
          const double v = (j + corners[e][1] + t * (corners[e + 1][1] - corners[e][1])) / cells;
          // Warps take u in [0,1): keep the far edges just inside.
          boundary.push_back(std::min(u, std::nextafter(1.0, 0.0)));
          boundary.push_back(std::min(v, std::nextafter(1.0, 0.0)));
        }
      const auto mapped = warp_sample(warp, boundary.data(), boundary.size() / 2);
      const std::size_t m = mapped.size() / 2;
      double area = 0, perimeter = 0;
      for (std::size_t k = 0; k < m; ++k) {
        const std::size_t next = (k + 1) % m;
        area += mapped[2 * k] * mapped[2 * next + 1] - mapped[2 * next] * mapped[2 * k + 1];
        perimeter += std::hypot(mapped[2 * next] - mapped[2 * k], mapped[2 * next + 1] - mapped[2 * k + 1]);
      }
      const double ratio = perimeter * perimeter / (4 * std::numbers::pi * std::fabs(area / 2));
      result.mean += ratio / (cells * cells);
      result.max = std::max(result.max, ratio);
    }
  return result;
}

/// The images of the grid's cell boundaries under `warp`: every line
/// u = i/cells and v = j/cells as a polyline of `steps` + 1 points
/// ([[x...], [y...]]), the far edges kept just inside [0, 1).
nlohmann::json warped_grid_lines(const Warp& warp, int cells, int steps) {
  nlohmann::json lines = nlohmann::json::array();
  const double last = std::nextafter(1.0, 0.0);
  for (int axis = 0; axis < 2; ++axis)
    for (int k = 0; k <= cells; ++k) {
      std::vector<double> u;
      for (int s = 0; s <= steps; ++s) {
        const double along = std::min(double(s) / steps, last), across = std::min(double(k) / cells, last);
        u.push_back(axis == 0 ? across : along);
        u.push_back(axis == 0 ? along : across);
      }
      const auto p = warp_sample(warp, u.data(), u.size() / 2);
      std::vector<double> x, y;
      for (std::size_t i = 0; i < p.size() / 2; ++i)
        x.push_back(std::round(p[2 * i] * 1e5) / 1e5), y.push_back(std::round(p[2 * i + 1] * 1e5) / 1e5);
      lines.push_back({x, y});
    }
  return lines;
}

/// Fraction of the unit disk on the far side of the line n·p = c (|n| = 1):
/// the circular segment's area (acos c − c√(1−c²)) over π.
double segment_fraction(double c) { return (std::acos(c) - c * std::sqrt(1 - c * c)) / std::numbers::pi; }

}  // namespace

Section disk_section(SectionContext& context) {
  Section section = context.start();
  const int cells = context.quick() ? 8 : 16;
  const unsigned runs = context.quick() ? 32 : 256;
  const std::uint64_t n = static_cast<std::uint64_t>(cells) * cells;
  const WarpParams no_params;
  const std::pair<std::string, std::string> maps[] = {{"disk-polar", "polar"}, {"disk-concentric", "concentric"}};

  // The picture: a jittered grid coloured by stratum, through each map.
  SamplerRequest request;
  request.n = n;
  request.d = 2;
  request.seed = context.seed();
  const PointSet grid = generate_points("jittered", request);
  nlohmann::json panels = nlohmann::json::array();
  std::vector<int> stratum(n);
  std::vector<double> x(n), y(n);
  for (std::size_t k = 0; k < n; ++k) {
    const int i = std::min(cells - 1, static_cast<int>(grid(k, 0) * cells));
    const int j = std::min(cells - 1, static_cast<int>(grid(k, 1) * cells));
    stratum[k] = ((j * 7) % cells) * cells + i;  // neighbouring rows get distant colours
    x[k] = grid(k, 0);
    y[k] = grid(k, 1);
  }
  panels.push_back({{"title", fmt::format("jittered {}×{} grid (U₁, U₂)", cells, cells)},
                    {"x", x},
                    {"y", y},
                    {"color", stratum},
                    {"grid", cells}});
  const std::map<std::string, std::string> formulas = {{"polar", "polar: θ = 2πU₁, r = √U₂"},
                                                       {"concentric", "concentric: r = U₁, θ = πU₂/(4U₁)"}};

  // Edge integrand: the indicator of x + y/2 > 0.25 over the disk.
  const double norm = std::hypot(1.0, 0.5), offset = 0.25 / norm;
  const double exact = segment_fraction(offset);
  Table table{"Strata images and jittered estimates of an edge integral over the disk",
              {"map", "mean P²/4πA", "max P²/4πA", "estimate variance", "mean error"},
              {}};
  std::vector<double> variances;
  for (const auto& [name, label] : maps) {
    const auto warp = make_warp(name, no_params);
    const auto mapped = warp_sample(*warp, grid.data.get(), n);
    std::vector<double> mx(n), my(n);
    for (std::size_t k = 0; k < n; ++k) mx[k] = mapped[2 * k], my[k] = mapped[2 * k + 1];
    panels.push_back({{"title", formulas.at(label)},
                      {"x", mx},
                      {"y", my},
                      {"color", stratum},
                      {"disk", true},
                      {"lines", warped_grid_lines(*warp, cells, 64)}});

    const Compactness compactness = strata_compactness(*warp, cells);
    double sum = 0, sum_squares = 0;
    for (unsigned r = 0; r < runs; ++r) {
      SamplerRequest run = request;
      run.seed = context.seed() + 1000 + r;
      const PointSet u = generate_points("jittered", run);
      const auto p = warp_sample(*warp, u.data.get(), n);
      double hits = 0;
      for (std::size_t k = 0; k < n; ++k) hits += (p[2 * k] + 0.5 * p[2 * k + 1]) / norm > offset;
      const double estimate = hits / n;
      sum += estimate;
      sum_squares += estimate * estimate;
    }
    const double mean = sum / runs, variance = (sum_squares - runs * mean * mean) / (runs - 1);
    variances.push_back(variance);
    table.rows.push_back({label, format_number(compactness.mean), format_number(compactness.max),
                          format_number(variance), format_number(mean - exact)});
    section.numbers[label] = {{"compactness_mean", compactness.mean},
                              {"compactness_max", compactness.max},
                              {"variance", variance},
                              {"mean_error", mean - exact}};
  }
  section.numbers["exact"] = exact;
  section.numbers["runs"] = runs;
  section.numbers["points"] = n;
  const auto& polar = section.numbers["polar"];
  const auto& concentric = section.numbers["concentric"];
  section.text.push_back(
      "The polar map takes θ = 2πU₁ and r = √U₂ (the square root makes it equi-areal: the disk's area within "
      "radius r is πr²). Shirley and Chiu's concentric map first rescales (U₁, U₂) to the square [−1, 1]², then "
      "on the wedge |U₂| ≤ U₁ takes r = U₁ and θ = πU₂/(4U₁) (the lecture's formula; the other three wedges by "
      "symmetry), so that the square of half-side r lands on the circle of radius r.");
  section.text.push_back(fmt::format(
      "Both maps are equi-areal, so a stratified grid stays stratified on the disk; but the polar map stretches "
      "strata into slivers (mean isoperimetric ratio {}, worst {}) while the concentric map keeps them compact "
      "(mean {}, worst {}; a square is {}).",
      format_number(polar["compactness_mean"]), format_number(polar["compactness_max"]),
      format_number(concentric["compactness_mean"]), format_number(concentric["compactness_max"]),
      format_number(4 / std::numbers::pi)));
  section.text.push_back(fmt::format(
      "Over {} jittered sets of {} points, the variance of the estimated area beyond an edge (exact {}) through the "
      "polar map is {}× that through the concentric map.",
      runs, n, format_number(exact, 4), format_number(variances[0] / variances[1])));
  section.figures.push_back(context.plot(
      "report_points", {{"columns", 3}, {"size", 3.4}, {"panels", panels}}, "maps",
      fmt::format("A jittered {0}×{0} grid, coloured by stratum, and its images under the two maps with the strata's "
                  "boundaries drawn: the polar map (θ = 2πU₁, r = √U₂) turns the strata into thin wedges and rings, "
                  "Shirley and Chiu's concentric map (on the wedge |U₂| ≤ U₁ of the square [−1, 1]², r = U₁, "
                  "θ = πU₂/(4U₁); the other wedges by symmetry) sends concentric squares to concentric circles and "
                  "keeps the strata compact",
                  cells)));
  section.tables.push_back(std::move(table));
  section.try_it = {"stratum warp -m disk-concentric -s jittered -n 256"};
  return section;
}

}  // namespace stratum::report
