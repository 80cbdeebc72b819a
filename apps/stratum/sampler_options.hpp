#pragma once
/// The options every sampler-taking subcommand shares, added by one function
/// so that they read the same everywhere: -s/--sampler SPEC (the grammar of
/// docs/samplers.md), -p/--param KEY=VALUE (the sampler's parameters,
/// repeatable), --randomize (the :RANDOMIZER part) and --seed; plus the seed
/// and thread options of the commands without a sampler.
#include <CLI/CLI.hpp>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "stratum/registry.hpp"
#include "stratum/registry/spec.hpp"

namespace stratum::cli {

/// The sampler of a subcommand as given on its command line.
struct SamplerOptions {
  SamplerOptions() = default;
  /// `default_sampler`: the spec used when -s is not given.
  explicit SamplerOptions(std::string default_sampler) : sampler(std::move(default_sampler)) {}

  std::string sampler;              ///< -s/--sampler: the spec text
  std::vector<std::string> params;  ///< -p/--param KEY=VALUE items
  std::string randomize;            ///< --randomize
  std::uint64_t seed = 0;           ///< --seed

  bool given() const { return !sampler.empty(); }
  /// The spec with -p and --randomize folded in; throws naming both forms on a conflict.
  SamplerSpec spec() const { return combine_sampler_options(sampler, params, randomize); }
  /// A request for spec(): params, randomizer and seed set (n, d, threads left to the caller).
  SamplerRequest request(const SamplerSpec& spec) const;
};

/// Adds -s/--sampler (with `sampler_help`), -p/--param, --randomize and --seed
/// (with `seed_help`) to `command`, and a footer pointing at docs/samplers.md.
/// The seed is parsed strictly (parse_seed) while the command line is read.
CLI::Option* add_sampler_options(CLI::App& command, SamplerOptions& options, const std::string& sampler_help,
                                 const std::string& seed_help = "seed of the randomization");

/// The footer of the --help of every sampler-taking subcommand.
void add_spec_footer(CLI::App& command);

/// --seed into `seed`: exactly the integers in [0, 2^64) (parse_seed).
CLI::Option* add_seed_option(CLI::App& command, std::uint64_t& seed, const std::string& help);

/// --threads into `threads` with the one thread rule (resolve_threads: 0 = every core).
CLI::Option* add_threads_option(CLI::App& command, std::int64_t& threads, const std::string& help);
CLI::Option* add_threads_option(CLI::App& command, unsigned& threads, const std::string& help);

/// Every number option of `app` and its subcommands (those CLI11 types INT,
/// UINT or FLOAT) read by the one number syntax of the parameter schema
/// (stratum/registry/params.hpp) instead of CLI11's: decimal integers only
/// ("010" is ten; "0x10" and "1e3" are refused, where CLI11 would read octal
/// and hex), no silent clamp of an integer that does not fit (CLI11 turns
/// 99999999999999999999 into 2^63 - 1), finite reals only (no "inf", "nan",
/// 1e999 or an underflow to 0). A refused value is an invalid_argument
/// naming the option and the text given.
void read_numbers_strictly(CLI::App& app);

/// A command line that names no command stratum has (exit status 2, as
/// every bad argument).
struct usage_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Throws usage_error for the first word of `argv` that names no
/// subcommand where `app` (or the subcommand before it) needs one, listing
/// the valid names: CLI11 says only "A subcommand is required".
void check_subcommand_names(const CLI::App& app, int argc, const char* const* argv);

}  // namespace stratum::cli
