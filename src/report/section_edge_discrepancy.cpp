/// §10, the edge-discrepancy slide: D(ℓ) = |fraction of the samples on one
/// side of a line ℓ − the area on that side|, and its supremum over all
/// lines (Mitchell 1992, "Ray tracing and irregularities of distribution";
/// exact by Dobkin, Eppstein & Mitchell 1996, "Computing the discrepancy
/// with applications to supersampling patterns"). It is the largest error of
/// the coverage a pixel's samples give a straight black-and-white edge. The
/// lecture's setting is SGI's multisampling: 1, 2, 4 or 8 samples on an 8×8
/// subpixel grid. Measured here: standard patterns on that grid (the
/// Direct3D/Vulkan 8× pattern, which lies on it; an ordered and a rotated
/// 2×2 grid), the best N-rooks pattern on the grid by exhaustive search, and
/// the lecture's other patterns at 16 and more points.
#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include "sections.hpp"
#include "stratum/analysis/edge_discrepancy.hpp"
#include "stratum/registry.hpp"
#include "stratum/util/hash.hpp"

namespace stratum::report {

namespace {

namespace sa = stratum::analysis;

constexpr int grid = 8;  ///< subpixels per axis

/// A pattern on the 8×8 grid: subpixel (column, row) pairs, samples at subpixel centres.
struct GridPattern {
  std::string name;
  std::vector<std::array<int, 2>> cells;
};

std::vector<double> grid_points(const std::vector<std::array<int, 2>>& cells) {
  std::vector<double> xy;
  for (const auto& [column, row] : cells) xy.insert(xy.end(), {(column + 0.5) / grid, (row + 0.5) / grid});
  return xy;
}

/// One sample p (the library's sweep needs two): every line through p has
/// D = max(A, 1 − A), lines missing p are limits of those, so the supremum is
/// 1 − the smallest area a line through p cuts off. Found by scanning the
/// direction (20000 steps) and refining about the best one (a maximum of a
/// smooth function of the angle, so the refinement converges).
sa::EdgeDiscrepancy single_sample(double px, double py) {
  const auto at = [&](double angle) {
    const double nx = std::cos(angle), ny = std::sin(angle), offset = nx * px + ny * py;
    const double area = sa::half_plane_area(nx, ny, offset);
    return sa::EdgeDiscrepancy{std::max(area, 1 - area), {angle, offset}};
  };
  sa::EdgeDiscrepancy best = at(0);
  double step = std::acos(-1.0) / 20000;
  for (int i = 1; i < 20000; ++i)
    if (const auto d = at(i * step); d.value > best.value) best = d;
  for (int round = 0; round < 4; ++round, step /= 1000) {
    const double centre = best.line.angle;
    for (int i = -1000; i <= 1000; ++i)
      if (const auto d = at(centre + i * step / 1000); d.value > best.value) best = d;
  }
  return best;
}

sa::EdgeDiscrepancy exact(const std::vector<double>& xy) {
  if (xy.size() == 2) return single_sample(xy[0], xy[1]);
  return sa::edge_discrepancy({xy.data(), xy.size() / 2, 2}, 1);
}

/// The largest D(ℓ) over horizontal and vertical lines only (the edges that
/// alias most visibly). On such lines the supremum is attained through a
/// sample, and D(ℓ) counts a sample on ℓ both ways.
double axis_aligned_discrepancy(const std::vector<double>& xy) {
  const sa::PointView view{xy.data(), xy.size() / 2, 2};
  double worst = 0;
  for (std::size_t i = 0; i < view.n; ++i)
    for (const int axis : {0, 1}) {
      const sa::EdgeLine line{axis == 0 ? 0.0 : std::acos(0.0), xy[2 * i + axis]};
      worst = std::max(worst, sa::line_discrepancy(view, line));
    }
  return worst;
}

/// Offsets in 1/16 pixel from the centre → subpixel of the 8×8 grid (odd offsets are subpixel centres).
std::array<int, 2> from_sixteenths(int x, int y) { return {(x + 7) / 2, (y + 7) / 2}; }

std::vector<GridPattern> standard_patterns() {
  std::vector<GridPattern> patterns{
      {"1 sample: the subpixel next to the centre", {{4, 4}}},
      {"2 samples on a diagonal", {{2, 2}, {5, 5}}},
      {"4 samples, ordered 2×2 grid", {{2, 2}, {5, 2}, {2, 5}, {5, 5}}},
      {"4 samples, rotated grid",
       {from_sixteenths(3, 5), from_sixteenths(-5, 3), from_sixteenths(-3, -5), from_sixteenths(5, -3)}},
  };
  // The Direct3D 10.1 / Vulkan standard 8× positions, in 1/16 pixel from the centre.
  const int d3d[8][2] = {{1, -3}, {-1, 3}, {5, 1}, {-3, -5}, {-5, 5}, {-7, -1}, {3, 7}, {7, -7}};
  GridPattern eight{"8 samples, Direct3D/Vulkan standard pattern", {}};
  for (const auto& [x, y] : d3d) eight.cells.push_back(from_sixteenths(x, y));
  patterns.push_back(std::move(eight));
  return patterns;
}

/// Every k-subset of {0..7} as a sorted list.
std::vector<std::vector<int>> subsets(int k) {
  std::vector<std::vector<int>> result;
  for (int mask = 0; mask < (1 << grid); ++mask) {
    if (__builtin_popcount(mask) != k) continue;
    std::vector<int> set;
    for (int b = 0; b < grid; ++b)
      if (mask & (1 << b)) set.push_back(b);
    result.push_back(std::move(set));
  }
  return result;
}

/// The N-rooks pattern of N samples on the grid (distinct columns, distinct
/// rows) with the lowest exact edge discrepancy, by exhaustive search; the
/// first in enumeration order among equals.
struct BestRooks {
  GridPattern pattern;
  double value = INFINITY;
  std::uint64_t searched = 0;
};

BestRooks best_rooks(int n) {
  BestRooks best;
  const auto sets = subsets(n);
  for (const auto& columns : sets)
    for (const auto& rows : sets) {
      std::vector<int> order(n);
      std::iota(order.begin(), order.end(), 0);
      do {
        std::vector<std::array<int, 2>> cells;
        for (int k = 0; k < n; ++k) cells.push_back({columns[k], rows[order[k]]});
        const double value = exact(grid_points(cells)).value;
        ++best.searched;
        if (value < best.value - 1e-12) best.value = value, best.pattern.cells = cells;
      } while (std::next_permutation(order.begin(), order.end()));
    }
  best.pattern.name = fmt::format("{}, the best N-rooks pattern on the grid", counted(n, "sample"));
  return best;
}

nlohmann::json line_json(const sa::EdgeLine& line) { return {{"angle", line.angle}, {"offset", line.offset}}; }

nlohmann::json panel_of(const std::string& title, const std::vector<double>& xy, const sa::EdgeLine& line, int cells) {
  std::vector<double> x, y;
  for (std::size_t i = 0; i + 1 < xy.size(); i += 2) x.push_back(xy[i]), y.push_back(xy[i + 1]);
  nlohmann::json panel = {{"title", title}, {"x", x}, {"y", y}, {"line", line_json(line)}};
  if (cells > 0) panel["grid"] = cells;
  return panel;
}

struct Measured {
  double mean = 0, error = 0;
  std::vector<double> example;  ///< realization 0
  sa::EdgeLine line;            ///< its attaining line
};

Measured measure_pattern(const sa::SamplerChoice& choice, std::uint64_t n, unsigned runs, std::uint64_t seed,
                         unsigned threads) {
  Measured result;
  std::vector<double> values;
  for (unsigned r = 0; r < runs; ++r) {
    SamplerRequest request;
    request.n = n;
    request.d = 2;
    request.seed = hash64(seed, n, r);
    request.randomize = choice.randomize;
    request.params = choice.params;
    const PointSet points = generate_points(choice.name, request);
    const sa::EdgeDiscrepancy d = sa::edge_discrepancy({points.data.get(), points.n, 2}, threads);
    values.push_back(d.value);
    if (r == 0) result.example.assign(points.data.get(), points.data.get() + 2 * points.n), result.line = d.line;
  }
  for (double v : values) result.mean += v / values.size();
  double squares = 0;
  for (double v : values) squares += (v - result.mean) * (v - result.mean);
  result.error = values.size() > 1 ? std::sqrt(squares / (values.size() - 1) / values.size()) : 0;
  return result;
}

}  // namespace

Section edge_discrepancy_section(SectionContext& context) {
  Section section = context.start();

  // 1, 2, 4, 8 samples on the 8×8 grid: standard patterns and the best N-rooks ones.
  std::vector<GridPattern> patterns = standard_patterns();
  std::uint64_t searched = 0;
  for (const int n : {1, 2, 4, 8}) {
    BestRooks best = best_rooks(n);
    searched += best.searched;
    patterns.push_back(std::move(best.pattern));
  }
  std::sort(patterns.begin(), patterns.end(),
            [](const GridPattern& a, const GridPattern& b) { return a.cells.size() < b.cells.size(); });
  Table grid_table{
      "Exact edge discrepancy of multisampling patterns on the 8×8 subpixel grid (samples at subpixel "
      "centres)",
      {"pattern", "subpixels (column, row)", "edge discrepancy", "lower bound 1/(2N)",
       "horizontal and vertical edges only"},
      {}};
  nlohmann::json panels = nlohmann::json::array();
  for (const GridPattern& pattern : patterns) {
    const std::vector<double> xy = grid_points(pattern.cells);
    const sa::EdgeDiscrepancy d = exact(xy);
    const double axis = axis_aligned_discrepancy(xy);
    const std::size_t n = pattern.cells.size();
    std::string cells;
    for (const auto& [c, r] : pattern.cells) cells += fmt::format("{}({}, {})", cells.empty() ? "" : " ", c, r);
    grid_table.rows.push_back(
        {pattern.name, cells, format_number(d.value), format_number(0.5 / n), format_number(axis)});
    section.numbers["grid_patterns"].push_back({{"name", pattern.name},
                                                {"n", n},
                                                {"cells", pattern.cells},
                                                {"edge_discrepancy", d.value},
                                                {"line", line_json(d.line)},
                                                {"lower_bound", 0.5 / n},
                                                {"axis_aligned", axis}});
    panels.push_back(panel_of(fmt::format("{}\nD = {}", pattern.name, format_number(d.value)), xy, d.line, grid));
  }
  section.numbers["searched_patterns"] = searched;
  section.figures.push_back(context.plot(
      "report_points", {{"columns", 3}, {"size", 3.4}, {"panels", panels}}, "grid-patterns",
      "Multisampling patterns on the 8×8 subpixel grid; red: a line attaining the exact edge discrepancy, shaded: "
      "the side whose sample fraction and area differ by D"));
  section.tables.push_back(std::move(grid_table));

  // The lecture's other patterns.
  const std::vector<std::uint64_t> counts =
      context.quick() ? std::vector<std::uint64_t>{16, 64} : std::vector<std::uint64_t>{16, 256};
  const unsigned runs = context.quick() ? 6 : 24;
  const std::vector<sa::SamplerChoice> lecture{{"random", "", {}},      {"jittered", "", {}},
                                               {"n-rooks", "", {}},     {"poisson-disk", "", {{"periodic", "1"}}},
                                               {"zaremba", "none", {}}, {"hammersley", "none", {}},
                                               {"sobol", "owen", {}}};
  Table pattern_table{fmt::format("Exact edge discrepancy of the lecture's patterns: mean ± standard error over {} "
                                  "realizations (one set for a deterministic pattern)",
                                  runs),
                      {"pattern"},
                      {}};
  for (const auto n : counts) pattern_table.header.push_back(fmt::format("N = {}", n));
  pattern_table.header.push_back("lower bound 1/(2N) at the largest N");
  nlohmann::json lecture_panels = nlohmann::json::array();
  for (const auto& choice : lecture) {
    std::vector<std::string> row{named_with_spec(choice)};
    for (const auto n : counts) {
      const bool deterministic = choice.name == "zaremba" || choice.name == "hammersley";
      const Measured m = measure_pattern(choice, n, deterministic ? 1 : runs, context.seed(), context.threads());
      row.push_back(m.error > 0 ? fmt::format("{} ± {}", format_number(m.mean), format_number(m.error, 2))
                                : format_number(m.mean));
      section.numbers["lecture_patterns"][sampler_spec(choice)].push_back(
          {{"n", n}, {"mean", m.mean}, {"standard_error", m.error}, {"line", line_json(m.line)}});
      if (n == counts.front())
        lecture_panels.push_back(
            panel_of(fmt::format("{}, N = {}\nD = {}", capitalized(sampler_name(choice)), n, format_number(m.mean)),
                     m.example, m.line, 0));
    }
    row.push_back(format_number(0.5 / double(counts.back())));
    pattern_table.rows.push_back(std::move(row));
  }
  section.figures.push_back(context.plot(
      "report_points", {{"columns", 4}, {"size", 2.6}, {"panels", lecture_panels}}, "lecture-patterns",
      fmt::format("The lecture's patterns at N = {} (one realization each) with a line attaining their exact edge "
                  "discrepancy",
                  counts.front())));
  section.tables.push_back(std::move(pattern_table));
  section.numbers["runs"] = runs;
  section.numbers["counts"] = counts;

  // The sentences, from the numbers.
  const auto& g = section.numbers["grid_patterns"];
  const auto value_of = [&](const std::string& prefix) {
    for (const auto& p : g)
      if (p["name"].get<std::string>().rfind(prefix, 0) == 0) return p;
    throw std::logic_error("edge-discrepancy section: no pattern " + prefix);
  };
  const auto one = value_of("1 sample:"), ordered = value_of("4 samples, ordered"),
             rotated = value_of("4 samples, rotated"), d3d = value_of("8 samples, Direct3D"),
             best8 = value_of("8 samples, the best");
  section.text.push_back(
      "A line ℓ through a pixel cuts it into two parts; D(ℓ) is the difference between the fraction of the "
      "pixel's samples on one side and that side's area, and the edge discrepancy is its largest value over every "
      "line (computed exactly, by rotational sweeps about every sample). For a pixel crossed by the straight edge "
      "of a black shape on white, the covered fraction of samples is the pixel's value and the area is the "
      "right one: the edge discrepancy is the worst error, as a fraction of the full contrast, that the pattern "
      "makes on any edge.");
  section.text.push_back(fmt::format(
      "No pattern of N samples does better than 1/(2N): sweeping a line across the pixel, the area grows "
      "continuously while the sample count jumps by whole samples. With one sample the error reaches {} (an edge "
      "either covers the sample or not); on the 8×8 grid the best patterns of 2, 4 and 8 samples (found by "
      "searching all {} N-rooks placements) reach {}, {} and {}, against the bounds 0.25, 0.125 and 0.0625.",
      format_number(one["edge_discrepancy"]), searched,
      format_number(value_of("2 samples, the best")["edge_discrepancy"]),
      format_number(value_of("4 samples, the best")["edge_discrepancy"]), format_number(best8["edge_discrepancy"])));
  section.text.push_back(fmt::format(
      "For nearly horizontal or vertical edges, the ones that alias most visibly, the ordered 2×2 grid has only "
      "two distinct rows: its error on such edges is {} against the rotated grid's {} (its four samples in four "
      "rows and four columns), and over all edges {} against {}. The Direct3D/Vulkan 8× pattern reaches {} ({} "
      "on horizontal and vertical edges), the best 8-rooks pattern on the grid {}.",
      format_number(ordered["axis_aligned"]), format_number(rotated["axis_aligned"]),
      format_number(ordered["edge_discrepancy"]), format_number(rotated["edge_discrepancy"]),
      format_number(d3d["edge_discrepancy"]), format_number(d3d["axis_aligned"]),
      format_number(best8["edge_discrepancy"])));
  const auto& lp = section.numbers["lecture_patterns"];
  section.text.push_back(fmt::format(
      "At N = {} the lecture's patterns reach {} (random), {} (jittered), {} (N-rooks), {} (Poisson disk) and {} "
      "(Zaremba), against the bound {}: the worst edge through a pixel sampled randomly is off by {}× what the "
      "best one can be.",
      counts.front(), format_number(lp["random"][0]["mean"]), format_number(lp["jittered"][0]["mean"]),
      format_number(lp["n-rooks"][0]["mean"]), format_number(lp["poisson-disk"][0]["mean"]),
      format_number(lp["zaremba:none"][0]["mean"]), format_number(0.5 / double(counts.front())),
      format_number(lp["random"][0]["mean"].get<double>() / (0.5 / double(counts.front())))));
  section.try_it = {"stratum discrepancy -m edge -s jittered -n 16",
                    "stratum discrepancy -m edge -s sobol -n 64 --randomize owen --json",
                    "stratum study mitchell --counts 16,256 --sampler halton:owen"};
  return section;
}

}  // namespace stratum::report
