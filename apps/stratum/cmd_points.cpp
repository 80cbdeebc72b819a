/// `stratum points`: generate a point set from any registry sampler and write
/// it as text, CSV or .npy (stdout without -o; files written atomically).
#include <fmt/core.h>

#include <limits>

#include "commands.hpp"
#include "point_input.hpp"
#include "sampler_options.hpp"
#include "stratum/io/points.hpp"
#include "stratum/registry.hpp"
#include "stratum/util/error.hpp"

namespace stratum::cli {

namespace {
struct PointsOptions {
  SamplerOptions sampler;
  std::optional<std::int64_t> n;
  std::int64_t d = 2;
  std::uint64_t start = 0;
  std::optional<double> radius;
  std::int64_t threads = 0;
  std::string format;
  std::string output;
};

void run_points(const PointsOptions& options) {
  const SamplerSpec spec = options.sampler.spec();
  SamplerRequest request = options.sampler.request(spec);
  if (options.n) {
    require(*options.n >= 1, "n", *options.n, "must be a positive integer");
    request.n = static_cast<std::uint64_t>(*options.n);
  }
  require(options.d >= 1 && options.d <= std::numeric_limits<unsigned>::max(), "d", options.d,
          "must be a positive integer");
  request.d = static_cast<unsigned>(options.d);
  request.start = options.start;
  request.radius = options.radius;
  request.threads = static_cast<unsigned>(options.threads);
  TableOutput table_output(options.output, options.format);  // checked before the work
  const PointSet points = generate_points(spec.name, request);
  table_output.write(points);
}
}  // namespace

void add_points_command(CLI::App& app) {
  auto options = std::make_shared<PointsOptions>();
  auto* command = app.add_subcommand("points", "Generate points from a sampler");
  add_sampler_options(*command, options->sampler, "the sampler")->required();
  command->add_option("-n", options->n, "number of points (leave out for a maximal Poisson-disk set with --radius)");
  command->add_option("-d", options->d, "dimensions")->capture_default_str();
  command
      ->add_option_function<std::string>(
          "--start", [options](const std::string& text) { options->start = parse_uint64("start", text); },
          "index of the first point (sequences and random; an integer in [0, 2^64))")
      ->type_name("UINT")
      ->default_str("0");
  command->add_option("--radius", options->radius, "Poisson-disk radius");
  add_threads_option(*command, options->threads, "threads for bulk generation");
  command->add_option("--format", options->format, "txt|csv|npy (default: by the -o extension, else txt)");
  command->add_option("-o,--output", options->output, "output file (stdout when absent)");
  command->callback([options] { run_points(*options); });
}

}  // namespace stratum::cli
