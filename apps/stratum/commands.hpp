#pragma once
/// Each subcommand lives in its own file and registers itself on the app.
#include <CLI/CLI.hpp>

namespace stratum::cli {
void add_samplers_command(CLI::App& app);
void add_points_command(CLI::App& app);
}  // namespace stratum::cli
