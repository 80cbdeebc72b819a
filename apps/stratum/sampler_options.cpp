#include "sampler_options.hpp"

#include <charconv>

#include "stratum/util/error.hpp"

namespace stratum::cli {

namespace {
constexpr const char* spec_footer =
    "Sampler specs: NAME[(KEY=VALUE,...)][:RANDOMIZER], e.g. sobol:owen, poisson-disk(periodic=1),\n"
    "jittered(strata=4x8), lattice(generator=1,55,133):cp. -p KEY=VALUE adds a parameter, --randomize the\n"
    "randomizer; giving one twice is an error. See docs/samplers.md and `stratum samplers`.\n";

std::int64_t parse_threads(const std::string& text) {
  std::int64_t value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || ptr != end)
    throw invalid_argument("threads", text.empty() ? "''" : text,
                           "must be an integer in [0, " + std::to_string(max_threads) + "] (0: every core)");
  return value;
}
}  // namespace

SamplerRequest SamplerOptions::request(const SamplerSpec& spec) const {
  SamplerRequest request;
  request.randomize = spec.randomize;
  request.params = spec.params;
  request.seed = seed;
  return request;
}

void add_spec_footer(CLI::App& command) { command.footer(spec_footer); }

CLI::Option* add_sampler_options(CLI::App& command, SamplerOptions& options, const std::string& sampler_help,
                                 const std::string& seed_help) {
  auto* sampler = command.add_option("-s,--sampler", options.sampler,
                                     sampler_help + ": a spec NAME[(KEY=VALUE,...)][:RANDOMIZER] (docs/samplers.md)");
  command.add_option("-p,--param", options.params, "sampler parameter KEY=VALUE (repeatable; `stratum samplers --json` lists them)");
  command.add_option("--randomize", options.randomize,
                     "the sampler's randomizer, as the :RANDOMIZER of the spec (default: the sampler's own)");
  add_seed_option(command, options.seed, seed_help);
  add_spec_footer(command);
  return sampler;
}

CLI::Option* add_seed_option(CLI::App& command, std::uint64_t& seed, const std::string& help) {
  return command
      .add_option_function<std::string>(
          "--seed", [&seed](const std::string& text) { seed = parse_seed(text); }, help + " (an integer in [0, 2^64))")
      ->type_name("UINT")
      ->default_str(std::to_string(seed));
}

CLI::Option* add_threads_option(CLI::App& command, std::int64_t& threads, const std::string& help) {
  return command
      .add_option_function<std::string>(
          "--threads",
          [&threads](const std::string& text) { threads = static_cast<std::int64_t>(resolve_threads(parse_threads(text))); },
          help + " (0: every core)")
      ->type_name("INT")
      ->default_str(std::to_string(threads));
}

CLI::Option* add_threads_option(CLI::App& command, unsigned& threads, const std::string& help) {
  return command
      .add_option_function<std::string>(
          "--threads", [&threads](const std::string& text) { threads = resolve_threads(parse_threads(text)); },
          help + " (0: every core)")
      ->type_name("INT")
      ->default_str(std::to_string(threads));
}

}  // namespace stratum::cli
