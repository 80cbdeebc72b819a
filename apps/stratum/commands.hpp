#pragma once
/// Each subcommand lives in its own file and registers itself on the app.
#include <CLI/CLI.hpp>

namespace stratum::cli {
void add_samplers_command(CLI::App& app);           // cmd_samplers.cpp
void add_describe_command(CLI::App& app);           // cmd_describe.cpp
void add_points_command(CLI::App& app);             // cmd_points.cpp
void add_warp_command(CLI::App& app);               // cmd_warp.cpp
void add_integrate_command(CLI::App& app);          // cmd_integrate.cpp
void add_converge_command(CLI::App& app);           // cmd_converge.cpp
void add_discrepancy_command(CLI::App& app);        // cmd_discrepancy.cpp
void add_local_discrepancy_command(CLI::App& app);  // cmd_local_discrepancy.cpp
void add_koksma_hlawka_command(CLI::App& app);      // cmd_koksma_hlawka.cpp
void add_spectrum_command(CLI::App& app);           // cmd_spectrum.cpp
void add_pair_correlation_command(CLI::App& app);   // cmd_pair_correlation.cpp
void add_optimize_command(CLI::App& app);           // cmd_optimize.cpp
void add_render_command(CLI::App& app);             // cmd_render.cpp (only with the renderer built)
void add_compare_command(CLI::App& app);            // cmd_compare.cpp (only with the renderer built)
void add_report_command(CLI::App& app);             // cmd_report.cpp (only with the renderer built)
/// `stratum study NAME`: each study adds itself under the `study` command.
void add_study_mitchell_command(CLI::App& study);    // cmd_study_mitchell.cpp
void add_study_dimension_command(CLI::App& study);   // cmd_study_dimension.cpp
void add_study_importance_command(CLI::App& study);  // cmd_study_importance.cpp
void add_study_mis_command(CLI::App& study);         // cmd_study_mis.cpp
}  // namespace stratum::cli
