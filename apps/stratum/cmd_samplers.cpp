/// `stratum samplers`: every registry entry with its kind, dimensions,
/// randomizers and properties (or JSON with --json).
#include <fmt/core.h>
#include <fmt/ranges.h>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "sampler_options.hpp"
#include "schema_json.hpp"
#include "stratum/registry.hpp"

namespace stratum::cli {

static nlohmann::json flags_json(const SamplerFlags& flags) {
  return {{"index_addressable", flags.index_addressable}, {"progressive", flags.progressive},
          {"frames_continue", flags.frames_continue},     {"self_randomized", flags.self_randomized},
          {"zero_two_net", flags.zero_two_net},           {"space_time", flags.space_time},
          {"prefix_unbiased", flags.prefix_unbiased}};
}

static nlohmann::json sampler_json(const SamplerInfo& s) {
  const nlohmann::json params = params_json(s.params);
  return {{"name", s.name},
          {"kind", s.kind},
          {"description", s.description},
          {"min_dim", s.min_dim},
          {"max_dim", s.max_dim},
          {"flags", flags_json(s.flags)},
          {"properties", property_words(s)},
          {"randomizers", s.randomizers},
          {"randomizer_family", randomizer_family_name(s.randomization.family)},
          {"counts", s.counts},
          {"params", params}};
}

void add_samplers_command(CLI::App& app) {
  auto* command = app.add_subcommand("samplers", "List every sampler: name, kind, dimensions, properties");
  auto json = std::make_shared<bool>(false);
  command->add_flag("--json", *json, "print JSON (with each sampler's parameters)");
  add_spec_footer(*command);
  command->callback([json] {
    if (*json) {
      nlohmann::json list = nlohmann::json::array();
      for (const auto& s : samplers()) list.push_back(sampler_json(s));
      nlohmann::json randomizer_list = nlohmann::json::array();
      for (const auto& [name, description] : randomizers())
        randomizer_list.push_back({{"name", name}, {"description", description}});
      fmt::print("{}\n", nlohmann::json{{"samplers", list}, {"randomizers", randomizer_list}}.dump(2));
      return;
    }
    fmt::print("{:<18} {:<9} {:<10} {:<34} {}\n", "name", "kind", "dims", "randomize (default first)", "properties");
    for (const auto& s : samplers())
      fmt::print("{:<18} {:<9} {:<10} {:<34} {}\n", s.name, s.kind, fmt::format("{}-{}", s.min_dim, s.max_dim),
                 fmt::format("{}", fmt::join(s.randomizers, ",")), fmt::join(property_words(s), "; "));
  });
}

}  // namespace stratum::cli
