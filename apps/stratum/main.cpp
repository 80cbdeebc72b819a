/// The stratum command line: thin subcommands over the library and registry.
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <exception>
#include <system_error>

#include "commands.hpp"
#include "stratum/io/output_file.hpp"
#include "stratum/util/error.hpp"

int main(int argc, char** argv) {
  CLI::App app{"stratum: Monte Carlo and quasi-Monte Carlo sampling toolkit"};
  app.require_subcommand(1);
  stratum::cli::add_samplers_command(app);
  stratum::cli::add_points_command(app);
  stratum::cli::add_warp_command(app);
  stratum::cli::add_integrate_command(app);
  stratum::cli::add_converge_command(app);
  stratum::cli::add_discrepancy_command(app);
  stratum::cli::add_local_discrepancy_command(app);
  stratum::cli::add_koksma_hlawka_command(app);
  stratum::cli::add_spectrum_command(app);
#ifdef STRATUM_HAS_RENDER
  stratum::cli::add_render_command(app);
  stratum::cli::add_compare_command(app);
#endif
#ifdef STRATUM_HAS_REPORT
  stratum::cli::add_report_command(app);
#endif
  auto* study = app.add_subcommand("study", "Reproduce a study of the lecture (see `stratum study --help`)");
  study->require_subcommand(1);
  stratum::cli::add_study_mitchell_command(*study);
  stratum::cli::add_study_dimension_command(*study);
  stratum::cli::add_study_importance_command(*study);
  stratum::io::install_signal_cleanup();  // Ctrl-C or SIGTERM: no staging file is left behind
  try {
    app.parse(argc, argv);
    stratum::io::check_stdout();  // output lost on a full disk or a closed stdout is an error
  } catch (const CLI::ConversionError& e) {
    fmt::print(stderr, "stratum: error: {}: not a valid number for this option (see --help)\n", e.what());
    return 2;
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const stratum::invalid_argument& e) {
    fmt::print(stderr, "stratum: error: {}\n", e.what());
    return 2;
  } catch (const std::system_error& e) {  // fmt::print to a stdout that lost it (a full disk, a closed stdout)
    fmt::print(stderr, "stratum: error: stdout: output was lost ({})\n", e.code().message());
    return 1;
  } catch (const std::bad_alloc&) {
    fmt::print(stderr, "stratum: error: out of memory\n");
    return 3;
  } catch (const std::exception& e) {
    fmt::print(stderr, "stratum: error: {}\n", e.what());
    return 1;
  }
  return 0;
}
