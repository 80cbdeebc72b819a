/// `stratum optimize blue-noise`: the rank tile of sobol-bn, pmj02-bn or
/// lattice-bn (analysis/blue_noise.hpp),
/// written as a rank file (sequences/ranked_blue_noise.hpp) that `--param table=FILE`
/// reads; the committed defaults were made by this command (docs/blue-noise.md).
#include <fmt/core.h>

#include <chrono>
#include <ostream>

#include "commands.hpp"
#include "sampler_options.hpp"
#include "stratum/analysis/blue_noise.hpp"
#include "stratum/io/output_file.hpp"
#include "stratum/util/error.hpp"

namespace stratum::cli {
namespace {

struct OptimizeOptions {
  std::int64_t size = 128, dims = 8, max_spp = 16, integrands = 32, sweeps = 256;
  std::uint64_t seed = default_seed;
  std::string base = "sobol";
  std::string structure = "morton";
  std::string output;
  bool quiet = false;
};

std::uint32_t bounded(std::int64_t v, const char* name) {
  require(v >= 0 && v <= 1000000, name, v, "is out of range (see stratum optimize blue-noise --help)");
  return static_cast<std::uint32_t>(v);
}

void run_blue_noise(const OptimizeOptions& o) {
  analysis::BlueNoiseOptions options;
  options.base = blue_noise_base_from(o.base, "base");
  options.size = bounded(o.size, "size");
  options.dims = bounded(o.dims, "dims");
  options.max_spp = bounded(o.max_spp, "max-spp");
  options.integrands = bounded(o.integrands, "integrands");
  options.sweeps = bounded(o.sweeps, "sweeps");
  options.seed = o.seed;
  options.structure = blue_noise_structure_from(o.structure, "structure");
  analysis::check_blue_noise_options(options);
  io::OutputFile file("output", o.output);
  file.prepare();  // refused before the work
  const auto start = std::chrono::steady_clock::now();
  std::vector<analysis::BlueNoisePairReport> report;
  const BlueNoiseTable table =
      analysis::optimize_blue_noise(options, &report, [&](std::uint32_t pair, std::uint32_t pairs) {
        if (!o.quiet) fmt::print(stderr, "optimizing pair {} of {}\n", pair + 1, pairs);
      });
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string bytes = serialize_blue_noise_table(table);
  file.write([&](std::ostream& out) { out.write(bytes.data(), static_cast<std::streamsize>(bytes.size())); });
  file.commit();
  fmt::print(
      "# blue-noise rank tile of {} ({}) {}x{}, {} dims, seed {}, spp 1..{}, {} integrands per spp, {} sweeps: {} "
      "bytes in {:.1f} s\n",
      blue_noise_base_name(table.base), blue_noise_structure_name(table.structure), table.size, table.size, table.dims,
      table.seed, table.max_spp, table.integrands, table.sweeps, bytes.size(), seconds);
  fmt::print("# energy: blurred error over the test integrands, white = 1\n");
  fmt::print("# {:>4} {:>10} {:>10} {:>10}\n", "pair", "initial", "final", "accepted");
  for (std::size_t p = 0; p < report.size(); ++p)
    fmt::print("  {:>4} {:>10.4f} {:>10.4f} {:>10.4f}\n", p, report[p].initial_energy / report[p].white_energy,
               report[p].final_energy / report[p].white_energy,
               report[p].proposed ? double(report[p].accepted) / double(report[p].proposed) : 0.0);
}

}  // namespace

void add_optimize_command(CLI::App& app) {
  auto* optimize = app.add_subcommand(
      "optimize", "Generate optimized tables: blue-noise (the rank tiles of sobol-bn, pmj02-bn, lattice-bn)");
  optimize->require_subcommand(1);
  auto o = std::make_shared<OptimizeOptions>();
  auto* command = optimize->add_subcommand(
      "blue-noise",
      "the per-pixel ranks of sobol-bn, pmj02-bn or lattice-bn (which block of the shared randomized base sequence a "
      "pixel takes), swapped "
      "between pixels so that the blurred error of test heavisides is "
      "small (Heitz et al. 2019; Belcour & Heitz 2021); deterministic: the same options give the same bytes");
  command
      ->add_option("--base", o->base, "the base sequence: sobol, pmj02 or lattice (for sobol-bn, pmj02-bn, lattice-bn)")
      ->capture_default_str();
  command->add_option("--size", o->size, "tile side in pixels, a power of 2 in [16, 256]")->capture_default_str();
  command
      ->add_option("--dims", o->dims, "dimensions covered (even, [2, 64], lattice [2, 32]; pairs optimized one by one)")
      ->capture_default_str();
  add_seed_option(*command, o->seed, "seed of the ranks, test integrands and swaps");
  command->add_option("--max-spp", o->max_spp, "optimize for spp = 1, 2, 4, ..., this (a power of 2, <= 256)")
      ->capture_default_str();
  command->add_option("--integrands", o->integrands, "test heavisides per spp, [1, 1024]")->capture_default_str();
  command->add_option("--sweeps", o->sweeps, "swap proposals per pixel, [0, 100000]")->capture_default_str();
  command->add_option("-o,--output", o->output, "the rank file to write")->required();
  command
      ->add_option("--structure", o->structure,
                   "morton: every aligned 2^l x 2^l block of pixels holds 4^l consecutive ranks (as ZSobol), only the "
                   "ranks within each 2x2 block swapped; free: any two pixels swapped")
      ->capture_default_str();
  command->add_flag("-q,--quiet", o->quiet, "no progress on stderr");
  command->callback([o] { run_blue_noise(*o); });
}

}  // namespace stratum::cli
