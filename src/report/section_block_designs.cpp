/// §7 Block designs: the Latin square (each symbol once per row and column),
/// the N-rooks pattern (one sample per row and column of an N×N grid: N
/// samples instead of the N² a full grid needs; McKay, Beckman & Conover
/// 1979, "A comparison of three methods for selecting values of input
/// variables"; Shirley 1991, "Discrepancy as a quality measure for sample
/// distributions"), N-queens (no two samples on a diagonal either) and
/// multi-jittered sampling (Latin and jittered at once: Chiu, Shirley &
/// Wang 1994, "Multi-jittered sampling"; Kensler 2013, "Correlated
/// multi-jittered sampling"). Each pattern is drawn with its 1D projections
/// and its stratification is measured: the Latin property and t-value from
/// the measure registry, and direct counts per stratum, per cell and per
/// diagonal.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "sections.hpp"
#include "stratum/analysis/measures.hpp"
#include "stratum/registry.hpp"

namespace stratum::report {

namespace {

namespace sa = stratum::analysis;

/// The cell of coordinate `u` among `cells` equal intervals of [0,1].
std::size_t cell_of(double u, std::size_t cells) {
  return std::min(cells - 1, static_cast<std::size_t>(u * static_cast<double>(cells)));
}

/// What is measured of each pattern.
struct BlockProperties {
  bool latin = false;                      ///< one point in each 1/N stratum of every axis (measure "latin")
  std::size_t worst_count = 0;             ///< most points in one 1/N stratum
  std::size_t empty_strata = 0;            ///< empty 1/N strata over all axes
  std::size_t cell_min = 0, cell_max = 0;  ///< points per cell of the √N×√N grid, over every pair of axes
  std::size_t diagonal_pairs = 0;          ///< pairs of points on one diagonal of the N×N grid (axes 0, 1)
  double t_value = NAN;                    ///< as a net in base 2 (N a power of two), else NaN
  double star = NAN;                       ///< star discrepancy
};

BlockProperties measure(const PointSet& points, unsigned threads) {
  const sa::PointView view{points.data.get(), points.n, points.d};
  sa::MeasureRequest request;
  request.threads = threads;
  BlockProperties result;
  const auto latin = sa::compute_measure("latin", view, request);
  result.latin = latin.value == 1;
  result.worst_count = static_cast<std::size_t>(latin.extras.at("worst_count"));
  result.empty_strata = static_cast<std::size_t>(latin.extras.at("empty_strata"));
  if ((points.n & (points.n - 1)) == 0) result.t_value = sa::compute_measure("t-value", view, request).value;
  result.star = sa::compute_measure("star", view, request).value;

  const auto side = static_cast<std::size_t>(std::llround(std::sqrt(static_cast<double>(points.n))));
  result.cell_min = points.n;
  for (std::size_t a = 0; a < points.d; ++a)
    for (std::size_t b = a + 1; b < points.d; ++b) {
      std::vector<std::size_t> cells(side * side, 0);
      for (std::size_t i = 0; i < points.n; ++i)
        ++cells[cell_of(points(i, b), side) * side + cell_of(points(i, a), side)];
      result.cell_min = std::min(result.cell_min, *std::min_element(cells.begin(), cells.end()));
      result.cell_max = std::max(result.cell_max, *std::max_element(cells.begin(), cells.end()));
    }
  // Diagonals of the N×N grid: cells with equal i − j or equal i + j.
  std::vector<std::size_t> down(2 * points.n, 0), up(2 * points.n, 0);
  for (std::size_t i = 0; i < points.n; ++i) {
    const std::size_t x = cell_of(points(i, 0), points.n), y = cell_of(points(i, 1), points.n);
    ++down[x + points.n - y];
    ++up[x + y];
  }
  for (std::size_t k = 0; k < 2 * points.n; ++k)
    result.diagonal_pairs += down[k] * (down[k] - 1) / 2 + up[k] * (up[k] - 1) / 2;
  return result;
}

PointSet make(const std::string& name, std::uint64_t n, unsigned d, std::uint64_t seed,
              const std::string& randomize = "") {
  SamplerRequest request;
  request.n = n;
  request.d = d;
  request.seed = seed;
  request.randomize = randomize;
  return generate_points(name, request);
}

nlohmann::json scatter(const PointSet& points, const std::string& title, int grid) {
  std::vector<double> x(points.n), y(points.n);
  for (std::size_t i = 0; i < points.n; ++i) x[i] = points(i, 0), y[i] = points(i, 1);
  return {{"title", title}, {"x", x}, {"y", y}, {"grid", grid}, {"projections", true}};
}

std::string yes_no(bool value) { return value ? "yes" : "no"; }

/// A Latin square read off the points of the `latin-square` sampler: cell
/// (row, column) from the first two coordinates holds symbol ⌊m·z⌋.
struct LatinSquare {
  std::vector<std::vector<std::string>> symbols;  ///< first row = top row of the pictures
  bool each_once = true;  ///< one symbol per cell, every symbol once in each row and column (counted)
};

LatinSquare read_square(const PointSet& points, std::size_t m) {
  LatinSquare square;
  square.symbols.assign(m, std::vector<std::string>(m, "·"));
  std::vector<std::vector<int>> in_row(m, std::vector<int>(m, 0)), in_column = in_row, in_cell = in_row;
  for (std::size_t i = 0; i < points.n; ++i) {
    const std::size_t column = cell_of(points(i, 0), m), row = cell_of(points(i, 1), m);
    const std::size_t symbol = cell_of(points(i, 2), m);
    square.symbols[m - 1 - row][column] = std::string(1, static_cast<char>('A' + symbol));
    const bool first = ++in_row[row][symbol] == 1, first_in_column = ++in_column[column][symbol] == 1;
    square.each_once = square.each_once && first && first_in_column && ++in_cell[row][column] == 1;
  }
  return square;
}

}  // namespace

Section block_designs_section(SectionContext& context) {
  Section section = context.start();
  constexpr std::uint64_t shown = 16, side = 4;  // the pictures: N = 16 on a 4×4 grid
  const std::uint64_t n = context.quick() ? 256 : 1024;
  const auto table_side = static_cast<std::uint64_t>(std::llround(std::sqrt(static_cast<double>(n))));
  const std::uint64_t seed = context.seed();

  // The Latin squares: points (column, row, symbol) of an orthogonal array.
  const PointSet square = make("latin-square", shown, 3, seed);
  const LatinSquare small = read_square(square, side);
  const LatinSquare large = read_square(make("latin-square", 64, 3, seed), 8);
  nlohmann::json square_panel = scatter(square, "Latin square 4×4: (column, row)", side);
  const nlohmann::json panels = {scatter(make("jittered", shown, 2, seed), "jittered (4×4 strata)", side),
                                 scatter(make("n-rooks", shown, 2, seed), "N-rooks (16×16 rows, columns)", shown),
                                 scatter(make("n-queens", shown, 2, seed, "none"), "N-queens", shown),
                                 scatter(make("multi-jittered", shown, 2, seed), "multi-jittered (4×4 strata)", side),
                                 scatter(make("cmj", shown, 2, seed), "correlated multi-jittered", side),
                                 square_panel};
  section.figures.push_back(context.plot(
      "report_points", {{"columns", 3}, {"panels", panels}}, "patterns",
      "Block designs with N = 16 points, their 1D projections as ticks under and beside each square, grid lines "
      "at the strata: jittered for contrast, N-rooks, N-queens, multi-jittered, correlated multi-jittered, and "
      "the (column, row) projection of a 4×4 Latin square's points"));
  section.figures.push_back(context.plot(
      "report_latin_square",
      {{"squares",
        {{{"title", "4×4 (the points above)"}, {"symbols", small.symbols}},
         {{"title", "8×8"}, {"symbols", large.symbols}}}}},
      "squares",
      fmt::format("Latin squares from the latin-square sampler (each symbol once in every row and column: {})",
                  yes_no(small.each_once && large.each_once))));

  // The measured properties at a larger N.
  std::vector<std::pair<std::string, PointSet>> patterns;
  patterns.emplace_back("random", make("random", n, 2, seed));
  patterns.emplace_back("jittered", make("jittered", n, 2, seed));
  patterns.emplace_back("n-rooks", make("n-rooks", n, 2, seed));
  patterns.emplace_back("n-queens", make("n-queens", n, 2, seed, "none"));
  patterns.emplace_back("multi-jittered", make("multi-jittered", n, 2, seed));
  patterns.emplace_back("cmj", make("cmj", n, 2, seed));
  patterns.emplace_back("latin-square (3D)", make("latin-square", n, 3, seed));
  for (const auto& extra : context.extra_samplers()) {
    const std::string name = extra.randomize.empty() ? extra.name : extra.name + ":" + extra.randomize;
    try {
      patterns.emplace_back(name, make(extra.name, n, 2, seed, extra.randomize));
    } catch (const std::exception&) {
      // An extra sampler that cannot make exactly N points is left out of the table.
    }
  }
  Table table{fmt::format("Stratification measured at N = {} (2D; the Latin square in 3D, its cells over all three "
                          "2D projections)",
                          n),
              {"pattern", "Latin (one per 1/N stratum)", "most in a 1/N stratum", "empty 1/N strata",
               fmt::format("points per cell of {}×{}", table_side, table_side), "pairs on a diagonal of the N×N grid",
               "t (base 2)", "star discrepancy"},
              {},
              "stratification-counts"};
  for (const auto& [name, points] : patterns) {
    const BlockProperties p = measure(points, context.threads());
    table.rows.push_back(
        {name, yes_no(p.latin), std::to_string(p.worst_count), std::to_string(p.empty_strata),
         p.cell_min == p.cell_max ? std::to_string(p.cell_min) : fmt::format("{} … {}", p.cell_min, p.cell_max),
         std::to_string(p.diagonal_pairs), std::isfinite(p.t_value) ? fmt::format("{}", p.t_value) : "n/a",
         format_number(p.star)});
    section.numbers["patterns"][name] = {{"latin", p.latin},
                                         {"worst_count", p.worst_count},
                                         {"empty_strata", p.empty_strata},
                                         {"cell_min", p.cell_min},
                                         {"cell_max", p.cell_max},
                                         {"diagonal_pairs", p.diagonal_pairs},
                                         {"t_value", std::isfinite(p.t_value) ? nlohmann::json(p.t_value) : nullptr},
                                         {"star", p.star},
                                         {"d", points.d}};
  }
  section.numbers["n"] = n;
  section.numbers["latin_squares"] = {
      {{"m", side}, {"symbols", small.symbols}, {"each_symbol_once_per_row_and_column", small.each_once}},
      {{"m", 8}, {"symbols", large.symbols}, {"each_symbol_once_per_row_and_column", large.each_once}}};

  const auto& numbers = section.numbers["patterns"];
  const auto& rooks = numbers["n-rooks"];
  const auto& jittered = numbers["jittered"];
  section.text.push_back(fmt::format(
      "The 4×4 and 8×8 Latin squares have each symbol {} in every row and column. With N = {} points, N-rooks leaves "
      "{} of the 2N = {} axis strata of width 1/N empty, while jittered points (one per cell of a {}×{} grid) "
      "leave {} empty: a full grid that stratified each axis into N intervals would need N² = {} points, N-rooks "
      "uses N = {}.",
      small.each_once && large.each_once ? "once" : "not always once", n, rooks["empty_strata"].get<std::size_t>(),
      2 * n, table_side, table_side, jittered["empty_strata"].get<std::size_t>(), n * n, n));
  const auto& queens = numbers["n-queens"];
  const auto& multi = numbers["multi-jittered"];
  const auto cells_text = [](const nlohmann::json& p) {
    const auto low = p["cell_min"].get<std::size_t>(), high = p["cell_max"].get<std::size_t>();
    return low == high ? counted(low, "point") : fmt::format("{} to {} points", low, high);
  };
  section.text.push_back(fmt::format(
      "N-queens has {} pairs of points on a shared diagonal of the N×N grid (N-rooks {}); multi-jittered points "
      "{} Latin and hold {} per cell of the {}×{} grid (N-rooks: {}).",
      queens["diagonal_pairs"].get<std::size_t>(), rooks["diagonal_pairs"].get<std::size_t>(),
      multi["latin"].get<bool>() ? "are" : "are not", cells_text(multi), table_side, table_side, cells_text(rooks)));

  Table square_table{"The 4×4 Latin square drawn above (rows top to bottom as in the plot; symbols A–D)",
                     {"row", "1", "2", "3", "4"},
                     {}};
  for (std::size_t r = 0; r < side; ++r) {
    std::vector<std::string> row{std::to_string(r + 1)};
    row.insert(row.end(), small.symbols[r].begin(), small.symbols[r].end());
    square_table.rows.push_back(row);
  }
  section.tables.push_back(std::move(square_table));
  section.tables.push_back(std::move(table));
  section.try_it = {"stratum discrepancy -m latin -s n-rooks -n 16", "stratum points -s multi-jittered -n 16"};
  return section;
}

}  // namespace stratum::report
