#pragma once
/// The points a measuring command reads: a point FILE, or a registry
/// sampler's points (--sampler SPEC -n N [-d D] [-p KEY=VALUE] [--seed]
/// [--randomize]: the shared sampler options of sampler_options.hpp); and
/// where a command's table goes (-o FILE or stdout).
#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>

#include "sampler_options.hpp"
#include "stratum/io/points.hpp"
#include "stratum/registry.hpp"

namespace stratum::cli {

struct PointInput : SamplerOptions {
  std::string file;
  std::optional<std::int64_t> n, d;
  std::int64_t threads = 1;
};

/// Adds FILE, the sampler options (-s, -p, --randomize, --seed), -n and -d to `command`.
void add_point_input_options(CLI::App& command, PointInput& input);

/// The points: read from the file, or generated (default d = 2). Throws
/// invalid_argument naming the option for both or neither source, -n/-d
/// with a file, or a bad n or d.
PointSet load_points(const PointInput& input);

/// Writes `table` to `output` atomically (io::write_points_file), or to
/// stdout when `output` is empty or "-".
void write_table(const std::string& output, const PointSet& table, io::PointFormat format);

}  // namespace stratum::cli
