/// `stratum study mitchell`: Mitchell's (1992) comparison of patterns by
/// random-edge discrepancy, as a table (text or JSON) and a figure.
#include <fmt/core.h>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "sampler_options.hpp"
#include "stratum/io/output_file.hpp"
#include "stratum/plot.hpp"
#include "stratum/analysis/convergence.hpp"
#include "stratum/analysis/mitchell_study.hpp"
#include "stratum/util/error.hpp"

namespace stratum::cli {

namespace {
struct MitchellOptions {
  std::vector<std::int64_t> counts{16, 256, 1600};
  std::int64_t realizations = 20;
  std::int64_t lines = 10000;
  std::uint64_t seed = 0;
  std::int64_t threads = 0;
  bool json = false;
  std::string plot;
  std::vector<std::string> extras;  ///< name or name:randomizer
};

nlohmann::json to_json(const analysis::MitchellStudy& study) {
  nlohmann::json patterns = nlohmann::json::array();
  for (std::size_t p = 0; p < study.patterns.size(); ++p) {
    const auto& pattern = study.patterns[p];
    nlohmann::json cells = nlohmann::json::array();
    for (std::size_t requested : study.options.counts) {
      const auto& cell = study.cell(analysis::mitchell_pattern_id(pattern), requested);
      cells.push_back({{"requested", cell.requested},
                       {"n", cell.n},
                       {"rms", cell.rms.mean},
                       {"rms_se", cell.rms.error},
                       {"mean", cell.mean.mean},
                       {"mean_se", cell.mean.error},
                       {"max", cell.max.mean},
                       {"max_se", cell.max.error}});
    }
    const auto& spectrum = study.spectra[p];
    patterns.push_back({{"label", pattern.label},
                        {"sampler", pattern.sampler},
                        {"params", pattern.params},
                        {"cells", cells},
                        {"spectrum", {{"n", spectrum.n}, {"frequency", spectrum.frequency}, {"power", spectrum.power}}},
                        {"example", spectrum.example}});
  }
  return {{"study", "mitchell"},          {"measure", "edge-random"},
          {"lines", study.options.lines}, {"realizations", study.options.realizations},
          {"seed", study.options.seed},   {"counts", study.options.counts},
          {"patterns", patterns},         {"notes", study.notes}};
}

void run_mitchell(const MitchellOptions& options) {
  const auto figure = plot::prepare_plot("plot", options.plot);  // checked before the work
  analysis::MitchellStudyOptions study_options;
  study_options.counts.clear();
  for (std::int64_t n : options.counts) {
    require(n >= 2 && n <= 1000000, "counts", n, "each count must be in [2, 10^6]");
    study_options.counts.push_back(static_cast<std::size_t>(n));
  }
  require(options.realizations >= 1 && options.realizations <= 100000, "realizations", options.realizations,
          "must be in [1, 10^5]");
  require(options.lines >= 1 && options.lines <= 100000000, "lines", options.lines, "must be in [1, 10^8]");
  study_options.realizations = static_cast<std::size_t>(options.realizations);
  study_options.lines = static_cast<std::size_t>(options.lines);
  study_options.seed = options.seed;
  for (const auto& extra : options.extras) {
    const auto choice = analysis::parse_sampler_choice(extra);
    study_options.extra_patterns.push_back({extra, choice.name, choice.params, choice.randomize});
  }
  study_options.threads = static_cast<unsigned>(options.threads);
  const auto study = analysis::run_mitchell_study(study_options);
  const nlohmann::json data = to_json(study);
  if (figure) plot::write_plot("mitchell", data, *figure);
  if (options.json) fmt::print("{}\n", data.dump(2));
  else fmt::print("{}", analysis::mitchell_table(study));
}
}  // namespace

void add_study_mitchell_command(CLI::App& study) {
  auto options = std::make_shared<MitchellOptions>();
  auto* command = study.add_subcommand(
      "mitchell",
      "Random-edge discrepancy of Zaremba, jittered, Poisson-disk, N-rooks and random patterns (Mitchell 1992)");
  command->add_option("--counts", options->counts, "point counts, comma-separated")
      ->delimiter(',')
      ->capture_default_str();
  command->add_option("--realizations", options->realizations, "realizations K per pattern and count")
      ->capture_default_str();
  command->add_option("--lines", options->lines, "random lines L per realization")->capture_default_str();
  add_seed_option(*command, options->seed, "seed of patterns and lines");
  add_threads_option(*command, options->threads, "threads");
  command->add_option(
      "--sampler", options->extras,
      "an extra registry pattern, a spec NAME[(KEY=VALUE,...)][:RANDOMIZER] (docs/samplers.md), compared "
      "after Mitchell's five; repeatable");
  add_spec_footer(*command);
  command->add_flag("--json", options->json, "print the table as JSON");
  command->add_option("--plot", options->plot, "write a figure (PNG): each pattern, its radial spectrum, the table");
  command->callback([options] { run_mitchell(*options); });
}

}  // namespace stratum::cli
