/// `stratum pair-correlation`: the pair correlation function g(r) of a point
/// set (Öztireli & Gross 2012, with the small-radius normalization of
/// analysis/geometry.hpp): g ≈ 1 at every r for white noise, g ≈ 0 below
/// the Poisson radius of blue noise. A table of (r, g) rows, or JSON.
#include <fmt/core.h>

#include <nlohmann/json.hpp>

#include <algorithm>

#include "commands.hpp"
#include "point_input.hpp"
#include "stratum/analysis/geometry.hpp"
#include "stratum/analysis/measures.hpp"
#include "stratum/io/output_file.hpp"
#include "stratum/util/error.hpp"

namespace stratum::cli {

namespace {
namespace sa = stratum::analysis;

struct PairCorrelationOptions : PointInput {
  std::vector<double> radii;
  std::optional<double> sigma;
  std::int64_t count = 100;
  std::string format, output;
  bool json = false;
};

void run_pair_correlation(const PairCorrelationOptions& o) {
  require(o.count >= 1 && o.count <= 100000, "count", o.count, "must be an integer in [1, 100000]");
  if (o.json && !o.format.empty())
    throw invalid_argument("format", o.format, "--json prints JSON; give one of the two");
  if (o.json && !o.output.empty()) throw invalid_argument("output", o.output, "--json prints to stdout");
  TableOutput table_output(o.output, o.format);  // checked before the work
  const PointSet points = load_points(o);
  const sa::PointView view{points.data.get(), points.n, points.d};
  sa::check_unit_cube(view);
  sa::PairCorrelation grid;
  if (o.radii.empty() || !o.sigma) grid = sa::default_pair_correlation_grid(view.n, view.d, std::size_t(o.count));
  const std::vector<double>& radii = o.radii.empty() ? grid.radius : o.radii;
  const double sigma = o.sigma.value_or(grid.sigma);
  const sa::PairCorrelation g = sa::pair_correlation(view, radii, sigma, static_cast<unsigned>(o.threads));
  if (o.json) {
    nlohmann::json out = {{"n", view.n}, {"d", view.d}, {"sigma", g.sigma}, {"r", g.radius}, {"g", g.g}};
    io::write_stdout([&](std::ostream& stream) { stream << out.dump(2) << '\n'; });
    return;
  }
  PointSet table{g.radius.size(), 2, std::make_unique<double[]>(2 * g.radius.size())};
  for (std::size_t i = 0; i < g.radius.size(); ++i) table.data[2 * i] = g.radius[i], table.data[2 * i + 1] = g.g[i];
  table_output.write(table);
}
}  // namespace

void add_pair_correlation_command(CLI::App& app) {
  auto o = std::make_shared<PairCorrelationOptions>();
  auto* command = app.add_subcommand("pair-correlation",
                                     "Pair correlation g(r) of a point set (toroidal, Gaussian kernel): 1 for white "
                                     "noise, 0 inside blue noise's radius");
  add_point_input_options(*command, *o);
  command
      ->add_option("--radii", o->radii,
                   "radii r at which to estimate g, comma-separated (default: --count radii up to "
                   "2.5 densest-packing distances)")
      ->delimiter(',');
  command->add_option("--count", o->count, "how many default radii (1..100000)")->capture_default_str();
  command->add_option("--sigma", o->sigma, "the kernel's standard deviation (default: 0.1 densest-packing distance)");
  add_threads_option(*command, o->threads, "threads (results do not depend on it)");
  command->add_flag("--json", o->json, "print {n, d, sigma, r, g} as JSON");
  command->add_option("--format", o->format, "txt|csv|npy (default: by the -o extension, else txt)");
  command->add_option("-o,--output", o->output, "output file: rows r g (stdout when absent)");
  command->callback([o] { run_pair_correlation(*o); });
}

}  // namespace stratum::cli
