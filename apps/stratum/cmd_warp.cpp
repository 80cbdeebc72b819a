/// `stratum warp`: push uniform points from any registry sampler through a
/// registry warp and write each warped point followed by its pdf (txt, csv or
/// .npy; files written atomically, so bad input never leaves a partial file).
#include <fmt/core.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "commands.hpp"
#include "point_input.hpp"
#include "sampler_options.hpp"
#include "stratum/io/points.hpp"
#include "stratum/registry.hpp"
#include "stratum/util/error.hpp"
#include "stratum/warp_registry.hpp"

namespace stratum::cli {

namespace {
struct WarpOptions {
  std::string map;
  std::int64_t n = 0;
  SamplerOptions sampler{"random"};
  std::vector<std::string> warp_params;
  std::string format;
  std::string output;
  bool list = false;
};

/// "1.5,2,-3" (or "@FILE": whitespace- or comma-separated numbers) as doubles.
std::vector<double> parse_numbers(const std::string& key, const std::string& text) {
  std::string body = text;
  if (!text.empty() && text[0] == '@') {
    // A regular file only: a FIFO or /dev/zero would never end.
    body = io::read_regular_file(key, text.substr(1), std::uint64_t{1} << 30);
  }
  for (char& c : body)
    if (c == ',' || c == '\n' || c == '\t' || c == '\r') c = ' ';
  std::vector<double> values;
  std::istringstream words(body);
  for (std::string word; words >> word;) {
    char* end = nullptr;
    const double value = std::strtod(word.c_str(), &end);
    if (end != word.c_str() + word.size()) throw invalid_argument(key, word, "must be a number");
    values.push_back(value);
  }
  require(!values.empty(), key, text.empty() ? "''" : text, "needs at least one number");
  return values;
}

void list_warps() {
  for (const auto& info : warps()) {
    std::string params;
    for (const auto& spec : info.params) params += (params.empty() ? "" : "; ") + spec.name + ": " + spec.description;
    fmt::print("{:<32} {} (domain {}, pdf per {}{}){}\n", info.name, info.description, info.domain, info.measure,
               info.area_preserving ? ", area-preserving" : "", params.empty() ? "" : "\n    params: " + params);
  }
}

void run_warp(const WarpOptions& options) {
  if (options.list) return list_warps();
  require(options.n >= 1, "n", options.n, "must be a positive integer");
  WarpParams params;
  for (const auto& item : options.warp_params) {
    const auto equals = item.find('=');
    if (equals == std::string::npos || equals == 0)
      throw invalid_argument("warp-param", item, "must be written key=v1,v2,... or key=@FILE");
    const std::string key = item.substr(0, equals);
    params[key] = parse_numbers(key, item.substr(equals + 1));
  }
  TableOutput table_output(options.output, options.format);  // checked before the work
  const auto warp = make_warp(options.map, params);
  const SamplerSpec spec = options.sampler.spec();
  SamplerRequest request = options.sampler.request(spec);
  request.n = static_cast<std::uint64_t>(options.n);
  request.d = warp->input_dim();
  const PointSet u = generate_points(spec.name, request);
  const std::vector<double> points = warp_sample(*warp, u.data.get(), u.n);
  const std::vector<double> pdf = warp_pdf(*warp, points.data(), u.n);

  const std::size_t out_dim = warp->output_dim();
  PointSet rows{u.n, out_dim + 1, std::make_unique<double[]>(u.n * (out_dim + 1))};
  for (std::size_t i = 0; i < u.n; ++i) {
    for (std::size_t k = 0; k < out_dim; ++k) rows.data[i * rows.d + k] = points[i * out_dim + k];
    rows.data[i * rows.d + out_dim] = pdf[i];
  }
  table_output.write(rows);
}
}  // namespace

void add_warp_command(CLI::App& app) {
  auto options = std::make_shared<WarpOptions>();
  auto* command = app.add_subcommand("warp", "Warp uniform points to a domain; writes each point and its pdf");
  command->add_option("-m,--map", options->map, "warp name (see `stratum warp --list`)");
  command->add_option("-n", options->n, "number of points");
  add_sampler_options(*command, options->sampler, "sampler of the uniform input (2D for 2D warps)",
                      "seed of the sampler")
      ->capture_default_str();
  command->add_option("--warp-param", options->warp_params,
                      "warp parameter KEY=V1,V2,... or KEY=@FILE (repeatable)");
  command->add_option("--format", options->format, "txt|csv|npy (default: by the -o extension, else txt)");
  command->add_option("-o,--output", options->output, "output file (stdout when absent)");
  command->add_flag("--list", options->list, "list the warps with their domains and parameters");
  command->callback([options] { run_warp(*options); });
}

}  // namespace stratum::cli
