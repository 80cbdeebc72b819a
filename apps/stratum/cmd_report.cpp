/// `stratum report`: the lecture reproduced as one HTML page (LECTURE.md
/// §1–13), every figure and number computed by this run.
#ifdef STRATUM_HAS_REPORT
#include <fmt/core.h>

#include <algorithm>

#include "commands.hpp"
#include "sampler_options.hpp"
#include "stratum/distributed.hpp"
#include "stratum/report/report.hpp"
#include "stratum/util/error.hpp"

namespace stratum::cli {

namespace {

struct ReportCliOptions {
  report::ReportOptions report;
  std::string only;
  std::int64_t threads = 0;
  bool list = false;
  bool slides = false;
};

void run_report(ReportCliOptions& options) {
  if (options.list) {
    for (const auto& section : report::report_sections())
      fmt::print("{:<16} {:<4} {}\n", section.id, section.lecture, section.title);
    return;
  }
  if (options.slides) {
    for (const auto& slide : report::lecture_slides())
      fmt::print("{:<4} {:<16} {}{}\n", slide.lecture, slide.section, slide.title,
                 slide.formula.empty() ? "" : "  [" + slide.formula + "]");
    return;
  }
  // Its sections write figures as they go, from every process: one process only (docs/distributed.md).
  require(distributed::size() == 1, "processes", distributed::size(),
          "report runs as one process (its renders, studies and discrepancies split over MPI ranks when run "
          "as their own commands)");
  options.report.threads = static_cast<unsigned>(options.threads);
  options.report.only.clear();
  std::string_view rest = options.only;
  while (!rest.empty()) {
    const auto comma = std::min(rest.find(','), rest.size());
    if (comma > 0) options.report.only.emplace_back(rest.substr(0, comma));
    rest.remove_prefix(std::min(comma + 1, rest.size()));
  }
  const auto result = report::write_report(options.report, [](const std::string& line) {
    fmt::print(stderr, "stratum report: {}\n", line);
    std::fflush(stderr);
  });
  fmt::print("report written to {} ({} sections, {:.1f} s)\n", result.index, result.sections.size(), result.seconds);
}

}  // namespace

void add_report_command(CLI::App& app) {
  auto options = std::make_shared<ReportCliOptions>();
  auto* command =
      app.add_subcommand("report", "Reproduce the lecture as an HTML page: every section's figures and measurements");
  command->add_option("-o,--directory", options->report.directory, "Folder for index.html, report.json and figures/")
      ->capture_default_str();
  command->add_flag("--quick", options->report.quick, "Smaller N, runs and spp (about a minute); same sections");
  command->add_option(
      "--sampler", options->report.extra_samplers,
      "Extra sampler, a spec NAME[(KEY=VALUE,...)][:RANDOMIZER] (docs/samplers.md), added to the pattern "
      "comparisons; repeatable");
  add_spec_footer(*command);
  command->add_option("--only", options->only, "Comma-separated section ids to run (see --list)");
  add_threads_option(*command, options->threads, "Worker threads");
  add_seed_option(*command, options->report.seed, "Seed of every randomized measurement");
  command->add_option("--cache", options->report.cache_dir, "Folder of cached reference renders")
      ->capture_default_str();
  command->add_flag("--list", options->list, "List the sections and exit");
  command->add_flag("--slides", options->slides,
                    "List the lecture's slides (section, title, formula) and the section reproducing each, and exit");
  command->callback([options] { run_report(*options); });
}

}  // namespace stratum::cli
#endif
