/// `stratum warp`: push uniform points from any registry sampler through a
/// registry warp and write each warped point followed by its pdf (txt, csv or
/// .npy; files written atomically, so bad input never leaves a partial file).
#include <fmt/core.h>

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "commands.hpp"
#include "point_input.hpp"
#include "sampler_options.hpp"
#include "stratum/io/points.hpp"
#include "stratum/io/read_points.hpp"
#include "stratum/analysis/catalogue.hpp"
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
  std::string pdf_at, invert;  ///< point FILEs in the warp's domain
  bool list = false;
};

/// A --warp-param value as the schema's comma-separated text: "1.5,2,-3" as
/// given, or "@FILE" read (its numbers separated by whitespace or commas).
std::string warp_param_text(const std::string& key, const std::string& text) {
  if (text.empty() || text[0] != '@') return text;
  // A regular file only: a FIFO or /dev/zero would never end.
  const std::string body = io::read_regular_file(key, text.substr(1), std::uint64_t{1} << 30);
  std::string numbers;
  std::string word;
  const auto flush = [&] {
    if (!word.empty()) numbers += (numbers.empty() ? "" : ",") + word;
    word.clear();
  };
  for (char c : body) {
    if (c == ',' || std::isspace(static_cast<unsigned char>(c))) flush();
    else word += c;
  }
  flush();
  return numbers;
}

void list_warps() {
  for (const auto& info : warps()) {
    std::string params;
    for (const auto& param : info.params) params += "\n    " + analysis::describe_param(param);
    fmt::print("{:<32} {} (domain {}, pdf per {}{}){}\n", info.name, info.description, info.domain, info.measure,
               info.area_preserving ? ", area-preserving" : "", params);
  }
}

/// --pdf-at FILE: each point of the domain and its pdf; --invert FILE: each
/// point's preimage u (the inverse map, where the warp has one).
void run_on_points(const Warp& warp, const WarpOptions& options, TableOutput& table_output) {
  const bool invert = !options.invert.empty();
  const PointSet points = io::read_points_strict(invert ? options.invert : options.pdf_at);
  const std::size_t out_dim = warp.output_dim();
  if (points.d != out_dim)
    throw invalid_argument(invert ? "invert" : "pdf-at",
                           (invert ? options.invert : options.pdf_at) + " (" + std::to_string(points.d) + " columns)",
                           options.map + " maps to " + std::to_string(out_dim) + "-D points: give " +
                               std::to_string(out_dim) + " columns");
  if (invert) {
    const std::vector<double> u = warp_invert(warp, points.data.get(), points.n);
    PointSet rows{points.n, warp.input_dim(), std::make_unique<double[]>(u.size())};
    std::copy(u.begin(), u.end(), rows.data.get());
    return table_output.write(rows);
  }
  const std::vector<double> pdf = warp_pdf(warp, points.data.get(), points.n);
  PointSet rows{points.n, out_dim + 1, std::make_unique<double[]>(points.n * (out_dim + 1))};
  for (std::size_t i = 0; i < points.n; ++i) {
    for (std::size_t k = 0; k < out_dim; ++k) rows.data[i * rows.d + k] = points.data[i * out_dim + k];
    rows.data[i * rows.d + out_dim] = pdf[i];
  }
  table_output.write(rows);
}

void run_warp(const WarpOptions& options) {
  if (options.list) return list_warps();
  if (options.map.empty()) {  // before -n: the map is what a bare `stratum warp` lacks first
    std::string names;
    for (const auto& info : warps()) names += (names.empty() ? "" : ", ") + info.name;
    throw invalid_argument("map", "(missing)", "give -m MAP, one of " + names);
  }
  find_warp(options.map);
  const bool from_file = !options.pdf_at.empty() || !options.invert.empty();
  if (!options.pdf_at.empty() && !options.invert.empty())
    throw invalid_argument("invert", options.invert, "give --pdf-at FILE or --invert FILE, not both");
  if (from_file && options.n != 0)
    throw invalid_argument("n", std::to_string(options.n),
                           "--pdf-at/--invert read their points from the FILE; drop -n");
  if (!from_file) require(options.n >= 1, "n", options.n, "must be a positive integer");
  std::map<std::string, std::string> texts = parse_key_values("warp-param", options.warp_params);
  for (auto& [key, text] : texts) text = warp_param_text(key, text);
  const WarpParams params = parse_warp_params(options.map, texts);
  TableOutput table_output(options.output, options.format);  // checked before the work
  const auto warp = make_warp(options.map, params);
  if (from_file) return run_on_points(*warp, options, table_output);
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
  command->add_option("--warp-param", options->warp_params, "warp parameter KEY=V1,V2,... or KEY=@FILE (repeatable)");
  command->add_option("--format", options->format, "txt|csv|npy (default: by the -o extension, else txt)");
  command->add_option("-o,--output", options->output, "output file (stdout when absent)");
  command->add_option("--pdf-at", options->pdf_at,
                      "FILE of points in the map's domain: write each point and its pdf (instead of -s/-n)");
  command->add_option(
      "--invert", options->invert,
      "FILE of points in the map's domain: write each point's preimage u in [0,1)^d (instead of -s/-n)");
  command->add_flag("--list", options->list, "list the warps with their domains and parameters");
  command->callback([options] { run_warp(*options); });
}

}  // namespace stratum::cli
