#include "point_input.hpp"

#include <iostream>
#include <limits>

#include "stratum/io/read_points.hpp"
#include "stratum/util/error.hpp"

namespace stratum::cli {

void add_point_input_options(CLI::App& command, PointInput& input) {
  command.add_option("file", input.file, "point file (.txt whitespace, .csv, .npy float64); or use --sampler");
  add_sampler_options(command, input, "measure this sampler's points instead of a file",
                      "seed of the sampler's randomization");
  command.add_option("-n", input.n, "number of points (with --sampler)");
  command.add_option("-d", input.d, "dimensions (with --sampler; default 2)");
}

PointSet load_points(const PointInput& o) {
  if (o.file.empty() == o.sampler.empty())
    throw invalid_argument("input", o.file.empty() ? "(none)" : o.file + " and --sampler " + o.sampler,
                           "give either a point FILE or --sampler S -n N [-d D]");
  if (!o.file.empty()) {
    if (!o.params.empty() || !o.randomize.empty())
      throw invalid_argument(o.params.empty() ? "randomize" : "param",
                             o.params.empty() ? o.randomize : o.params.front(),
                             "applies only to --sampler; a FILE is read as it is");
    if (o.n || o.d) throw invalid_argument("-n/-d", o.file, "apply only to --sampler; a FILE has its own size");
    PointSet points = io::read_points_strict(o.file);
    io::check_unit_cube(points, o.file);  // here, where the file's lines are known
    return points;
  }
  require(o.n.has_value(), "n", "(missing)", "--sampler needs -n N");
  require(*o.n >= 1, "n", *o.n, "must be a positive integer");
  const std::int64_t d = o.d.value_or(2);
  require(d >= 1 && d <= std::numeric_limits<unsigned>::max(), "d", d, "must be a positive integer");
  const SamplerSpec spec = o.spec();
  SamplerRequest request = o.request(spec);
  request.n = static_cast<std::uint64_t>(*o.n);
  request.d = static_cast<unsigned>(d);
  request.threads = static_cast<unsigned>(o.threads);
  return generate_points(spec.name, request);
}

TableOutput::TableOutput(const std::string& output, const std::string& format)
    : format_(io::resolve_point_format(output, format)) {
  if (output.empty() || output == "-") return;
  file_ = std::make_unique<io::OutputFile>("output", output);
  file_->prepare();
}

void TableOutput::write(const PointSet& table) {
  if (file_) return io::write_points_file(*file_, table, format_);
  io::write_stdout([&](std::ostream& out) { io::write_points(out, table, format_); });
}

}  // namespace stratum::cli
