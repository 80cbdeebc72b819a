#pragma once
/// The points a measuring command reads: a point FILE, or a registry
/// sampler's points (--sampler SPEC -n N [-d D] [-p KEY=VALUE] [--seed]
/// [--randomize]: the shared sampler options of sampler_options.hpp); and
/// where a command's table goes (-o FILE or stdout).
#include <CLI/CLI.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "sampler_options.hpp"
#include "stratum/io/output_file.hpp"
#include "stratum/io/points.hpp"
#include "stratum/registry.hpp"

namespace stratum::cli {

struct PointInput : SamplerOptions {
  std::string file;
  std::optional<std::int64_t> n, d;
  std::int64_t threads = 1;  // add_threads_option makes it every core where the subcommand has --threads
};

/// Adds FILE, the sampler options (-s, -p, --randomize, --seed), -n and -d to `command`.
void add_point_input_options(CLI::App& command, PointInput& input);

/// The points: read from the file, or generated (default d = 2). Throws
/// invalid_argument naming the option for both or neither source, -n/-d
/// with a file, or a bad n or d.
PointSet load_points(const PointInput& input);

/// Where a command's table goes: -o FILE, prepared (checked, staged) when
/// constructed, before the command's work; or stdout when `output` is empty
/// or "-". The format follows --format or the extension (io::resolve_point_format).
class TableOutput {
 public:
  TableOutput(const std::string& output, const std::string& format);
  /// Writes the table (file: never half-written; stdout: every write checked).
  void write(const PointSet& table);
  bool to_file() const { return file_ != nullptr; }

 private:
  std::unique_ptr<io::OutputFile> file_;
  io::PointFormat format_;
};

}  // namespace stratum::cli
