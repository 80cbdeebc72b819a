/// `stratum points`: generate a point set from any registry sampler and write
/// it as text, CSV or .npy (stdout without -o; files written atomically).
#include <fmt/core.h>

#include <limits>

#include "commands.hpp"
#include "point_input.hpp"
#include "stratum/io/points.hpp"
#include "stratum/registry.hpp"
#include "stratum/util/error.hpp"

namespace stratum::cli {

namespace {
struct PointsOptions {
  std::string sampler;
  std::optional<std::int64_t> n;
  std::int64_t d = 2;
  std::uint64_t seed = 0;
  std::uint64_t start = 0;
  std::string randomize;
  std::optional<double> radius;
  std::int64_t threads = 1;
  std::string format;
  std::string output;
  std::vector<std::string> params;
};

void run_points(const PointsOptions& options) {
  SamplerRequest request;
  if (options.n) {
    require(*options.n >= 1, "n", *options.n, "must be a positive integer");
    request.n = static_cast<std::uint64_t>(*options.n);
  }
  require(options.d >= 1 && options.d <= std::numeric_limits<unsigned>::max(), "d", options.d,
          "must be a positive integer");
  require(options.threads >= 1 && options.threads <= 1024, "threads", options.threads, "must be in [1, 1024]");
  request.d = static_cast<unsigned>(options.d);
  request.seed = options.seed;
  request.start = options.start;
  request.randomize = options.randomize;
  request.radius = options.radius;
  request.threads = static_cast<unsigned>(options.threads);
  for (const auto& item : options.params) {
    const auto equals = item.find('=');
    if (equals == std::string::npos || equals == 0)
      throw invalid_argument("param", item, "must be written key=value");
    request.params[item.substr(0, equals)] = item.substr(equals + 1);
  }
  TableOutput table_output(options.output, options.format);  // checked before the work
  const PointSet points = generate_points(options.sampler, request);
  table_output.write(points);
}
}  // namespace

void add_points_command(CLI::App& app) {
  auto options = std::make_shared<PointsOptions>();
  auto* command = app.add_subcommand("points", "Generate points from a sampler");
  command->add_option("-s,--sampler", options->sampler, "sampler name (see `stratum samplers`)")->required();
  command->add_option("-n", options->n, "number of points (leave out for a maximal Poisson-disk set with --radius)");
  command->add_option("-d", options->d, "dimensions")->capture_default_str();
  command->add_option("--seed", options->seed, "seed of the randomization")->capture_default_str();
  command->add_option("--start", options->start, "index of the first point (sequences only)")->capture_default_str();
  command->add_option("--randomize", options->randomize,
                      "none|owen|owen-hash|xor|lms|permute|cp (default: the sampler's own)");
  command->add_option("--radius", options->radius, "Poisson-disk radius");
  command->add_option("--threads", options->threads, "threads for bulk generation")->capture_default_str();
  command->add_option("--format", options->format, "txt|csv|npy (default: by the -o extension, else txt)");
  command->add_option("-o,--output", options->output, "output file (stdout when absent)");
  command->add_option("-p,--param", options->params, "sampler parameter key=value (repeatable)");
  command->callback([options] { run_points(*options); });
}

}  // namespace stratum::cli
