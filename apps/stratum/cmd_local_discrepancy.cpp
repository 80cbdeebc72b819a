/// `stratum local-discrepancy`: the local discrepancy Δ(x, y) = n(x, y)/N − x·y
/// of a 2D point set on the (R+1) × (R+1) grid of corners (i/R, j/R), as a
/// table (row j holds y = j/R, column i x = i/R), and with --box the anchored
/// box where |Δ| reaches D*_N (LECTURE.md §10; analysis/local_discrepancy.hpp).
#include <fmt/core.h>

#include <algorithm>

#include "commands.hpp"
#include "point_input.hpp"
#include "stratum/analysis/local_discrepancy.hpp"
#include "stratum/analysis/measures.hpp"
#include "stratum/io/points.hpp"
#include "stratum/util/error.hpp"

namespace stratum::cli {

namespace {
namespace sa = stratum::analysis;

struct LocalOptions : PointInput {
  std::int64_t resolution = 64;
  std::string format, output;
  bool box = false;
};

void run_local(const LocalOptions& o) {
  require(o.resolution >= 1 && o.resolution <= 4096, "resolution", o.resolution, "must be in [1, 4096]");
  TableOutput table_output(o.output, o.format);  // checked before the work
  const PointSet points = load_points(o);
  const sa::PointView view{points.data.get(), points.n, points.d};
  require(view.d == 2, "d", view.d, "the local discrepancy needs 2D points");
  sa::check_unit_cube(view);
  // --box: the box line on stdout, and the grid only into -o FILE. Through
  // the registry's star-box, so the CLI and Python share its size limit
  // (the sweep is O(N^2)) and its message.
  if (o.box) {
    const sa::MeasureResult box = sa::compute_measure("star-box", view, {});
    const auto& e = box.extras;
    fmt::print("D* = {} at the box [0, {}) x [0, {}): {} points, {}\n", box.value, e.at("x"), e.at("y"),
               static_cast<std::size_t>(e.at("count")),
               e.at("closed") == 1.0 ? "too many (upper edges included, approached from above)" : "too few");
    if (o.output.empty() || o.output == "-") return;
  }
  const sa::LocalDiscrepancyGrid grid = sa::local_discrepancy_grid(view, static_cast<std::size_t>(o.resolution));
  const std::size_t side = grid.resolution + 1;
  PointSet table{side, side, std::make_unique<double[]>(side * side)};
  std::copy(grid.values.begin(), grid.values.end(), table.data.get());
  table_output.write(table);
}
}  // namespace

void add_local_discrepancy_command(CLI::App& app) {
  auto o = std::make_shared<LocalOptions>();
  auto* command = app.add_subcommand(
      "local-discrepancy", "Local discrepancy n(x,y)/N - xy of 2D points on a grid of corners; --box: where D* is");
  add_point_input_options(*command, *o);
  command->add_option("-r,--resolution", o->resolution, "R: the grid's corners are (i/R, j/R), i, j = 0..R (1..4096)")
      ->capture_default_str();
  command->add_flag(
      "--box", o->box,
      "print the box [0,x) x [0,y) attaining D* (O(N^2), N <= 20000); the grid then goes only to -o FILE");
  command->add_option("--format", o->format, "txt|csv|npy (default: by the -o extension, else txt)");
  command->add_option("-o,--output", o->output,
                      "output file: (R+1) rows of R+1 values, row j for y = j/R (stdout when absent)");
  command->callback([o] { run_local(*o); });
}

}  // namespace stratum::cli
