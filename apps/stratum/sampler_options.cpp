#include "sampler_options.hpp"

#include <charconv>
#include <functional>

#include "stratum/registry/params.hpp"

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
  command.add_option("-p,--param", options.params,
                     "sampler parameter KEY=VALUE (repeatable; `stratum samplers --json` lists them)");
  command.add_option("--randomize", options.randomize,
                     "the sampler's randomizer, as the :RANDOMIZER of the spec (default: the sampler's own)");
  add_seed_option(command, options.seed, seed_help);
  add_spec_footer(command);
  return sampler;
}

CLI::Option* add_seed_option(CLI::App& command, std::uint64_t& seed, const std::string& help) {
  seed = default_seed;
  return command
      .add_option_function<std::string>(
          "--seed", [&seed](const std::string& text) { seed = parse_seed(text); }, help + " (an integer in [0, 2^64))")
      ->type_name("UINT")
      ->default_str(std::to_string(seed));
}

// Every subcommand's default: every core (resolve_threads(0)); --threads 1
// for reproducible timing.
CLI::Option* add_threads_option(CLI::App& command, std::int64_t& threads, const std::string& help) {
  threads = static_cast<std::int64_t>(resolve_threads(0));
  return command
      .add_option_function<std::string>(
          "--threads",
          [&threads](const std::string& text) {
            threads = static_cast<std::int64_t>(resolve_threads(parse_threads(text)));
          },
          help + " (0: every core)")
      ->type_name("INT")
      ->default_str("0");
}

CLI::Option* add_threads_option(CLI::App& command, unsigned& threads, const std::string& help) {
  threads = resolve_threads(0);
  return command
      .add_option_function<std::string>(
          "--threads", [&threads](const std::string& text) { threads = resolve_threads(parse_threads(text)); },
          help + " (0: every core)")
      ->type_name("INT")
      ->default_str("0");
}

/// The name a message gives an option: its long name ("resolution"), else
/// its short one ("n"), else the positional's.
static std::string option_name(const CLI::Option& option) {
  if (!option.get_lnames().empty()) return option.get_lnames().front();
  if (!option.get_snames().empty()) return option.get_snames().front();
  return option.get_name(true);
}

/// Reads `text` by the schema's syntax for numbers of CLI11 type `type`
/// (INT, UINT or FLOAT) and rewrites it as plain decimal, so that CLI11's
/// own conversion (which reads "010" as octal) reads the number the schema
/// read. Throws invalid_argument naming `name`.
static void read_number(const std::string& name, const std::string& type, std::string& text) {
  if (type == "UINT") {
    text = std::to_string(parse_uint64(name, text));
  } else if (type == "INT") {
    const Param int64 = params::integer(name, "", "", half_open(-0x1p63, 0x1p63));
    text = std::to_string(std::get<std::int64_t>(parse_param(int64, text)));
  } else {
    parse_param(params::real(name, "", "", any_real()), text);
  }
}

void read_numbers_strictly(CLI::App& app) {
  for (CLI::Option* option : app.get_options()) {
    const std::string type = option->get_type_name();
    if (type != "INT" && type != "UINT" && type != "FLOAT") continue;
    const std::string name = option_name(*option);
    // --threads, --seed and --start are read by their own strict parsers
    // (parse_threads, parse_seed, parse_uint64), whose messages say their rule.
    if (name == "threads" || name == "seed" || name == "start") continue;
    option->transform(CLI::Validator(  // transform: it may rewrite the text (check() may not)
        [name, type](std::string& text) {
          read_number(name, type, text);
          return std::string();
        },
        "", "number"));
  }
  for (CLI::App* command : app.get_subcommands([](CLI::App*) { return true; })) read_numbers_strictly(*command);
}

namespace {

/// The names of `app`'s subcommands, comma-separated ("" when it has none).
std::string subcommand_names(const CLI::App& app) {
  std::string names;
  for (const CLI::App* command : app.get_subcommands([](const CLI::App*) { return true; }))
    names += (names.empty() ? "" : ", ") + command->get_name();
  return names;
}

}  // namespace

void check_subcommand_names(const CLI::App& app, int argc, const char* const* argv) {
  const CLI::App* at = &app;
  const auto of = [&] { return at == &app ? std::string() : " of " + at->get_name(); };
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (word.empty() || word.front() == '-') return;  // options, --help, --version: CLI11's to judge
    const std::string names = subcommand_names(*at);
    if (names.empty()) return;
    const CLI::App* next = nullptr;
    for (const CLI::App* command : at->get_subcommands([](const CLI::App*) { return true; }))
      if (command->check_name(word)) next = command;
    if (!next)
      throw usage_error("unknown subcommand '" + printable(word) + "'" + of() + ": valid subcommands are " + names);
    at = next;
  }
  // Every word was a subcommand name and the last one needs a subcommand of
  // its own (bare `stratum`, `stratum study`): say which, not CLI11's "A subcommand is required".
  const std::string names = subcommand_names(*at);
  if (names.empty()) return;
  std::string path;
  for (int i = 1; i < argc; ++i) path += std::string(" ") + argv[i];
  throw usage_error("give a subcommand" + of() + ": one of " + names + " (stratum" + path +
                    " SUBCOMMAND --help for its options)");
}

}  // namespace stratum::cli
