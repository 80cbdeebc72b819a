/// The stratum command line: thin subcommands over the library and registry.
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <exception>
#include <filesystem>
#include <string>
#include <system_error>

#include "commands.hpp"
#include "distributed_job.hpp"
#include "sampler_options.hpp"
#include "stratum/distributed.hpp"
#include "stratum/io/output_file.hpp"
#include "stratum/memory.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/interrupt.hpp"

int main(int argc, char** argv) {
  stratum::cli::DistributedJob job(argc, argv);  // an MPI rank under mpirun/srun
  CLI::App app{"stratum: Monte Carlo and quasi-Monte Carlo sampling toolkit"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("stratum ") + STRATUM_VERSION_TEXT, "print the version and exit");
  stratum::cli::add_samplers_command(app);
  stratum::cli::add_describe_command(app);
  stratum::cli::add_points_command(app);
  stratum::cli::add_warp_command(app);
  stratum::cli::add_integrate_command(app);
  stratum::cli::add_converge_command(app);
  stratum::cli::add_discrepancy_command(app);
  stratum::cli::add_local_discrepancy_command(app);
  stratum::cli::add_koksma_hlawka_command(app);
  stratum::cli::add_spectrum_command(app);
  stratum::cli::add_pair_correlation_command(app);
  stratum::cli::add_optimize_command(app);
#ifdef STRATUM_HAS_RENDER
  stratum::cli::add_render_command(app);
  stratum::cli::add_compare_command(app);
#endif
#ifdef STRATUM_HAS_REPORT
  stratum::cli::add_report_command(app);
#endif
  auto* study = app.add_subcommand("study", "Reproduce a study of the lecture: mitchell, dimension, importance or mis");
  study->require_subcommand(1);
  stratum::cli::add_study_mitchell_command(*study);
  stratum::cli::add_study_dimension_command(*study);
  stratum::cli::add_study_importance_command(*study);
  stratum::cli::add_study_mis_command(*study);
  stratum::io::install_signal_cleanup();  // Ctrl-C or SIGTERM: no staging file is left behind
  int code = 0;
  std::string message;
  stratum::cli::read_numbers_strictly(app);  // one number syntax: the parameter schema's
  try {
    stratum::cli::check_subcommand_names(app, argc, argv);
    app.parse(argc, argv);
    stratum::io::check_stdout();  // output lost on a full disk or a closed stdout is an error
  } catch (const CLI::ConversionError& e) {
    code = 2, message = fmt::format("{}: not a valid number for this option (see --help)", e.what());
  } catch (const CLI::ParseError& e) {
    // Usage errors and --help print themselves (on rank 0); every usage
    // error exits 2, as every bad argument does (CLI11's own codes are 100+).
    code = app.exit(e) == 0 ? 0 : 2;
  } catch (const stratum::cli::usage_error& e) {
    code = 2, message = e.what();
  } catch (const stratum::distributed::PeerFailure&) {
    code = 1;  // another rank failed and says why
  } catch (const stratum::interrupted& e) {
    code = 130, message = e.what();  // Ctrl-C, as a shell reports a process it ended (128 + SIGINT)
  } catch (const stratum::invalid_argument& e) {
    code = 2, message = e.what();
  } catch (const std::filesystem::filesystem_error& e) {
    code = 1, message = e.what();
  } catch (const std::system_error& e) {  // fmt::print to a stdout that lost it (a full disk, a closed stdout)
    code = 1, message = "stdout: output was lost (" + e.code().message() + ")";
  } catch (const stratum::memory_error& e) {
    code = 3, message = e.what();  // refused before allocating (stratum/memory.hpp)
  } catch (const std::bad_alloc&) {
    code = 3, message =
                  "out of memory: the system refused an allocation this command needs (ask for fewer points, "
                  "a smaller image or fewer threads; STRATUM_MEMORY_LIMIT sets the guard, docs/cli.md)";
  } catch (const std::exception& e) {
    code = 1, message = e.what();
  }
  return job.finish(code, message);
}
