/// `stratum describe NAME`: one registry entry's parameters from the schema
/// (text, --json), or every entry's (--all; --markdown writes the docs page).
#include <fmt/core.h>

#include "commands.hpp"
#include "schema_json.hpp"
#include "stratum/util/error.hpp"

namespace stratum::cli {

namespace {
struct DescribeOptions {
  std::string name;
  std::string kind;
  bool all = false, json = false, markdown = false;
};

void run_describe(const DescribeOptions& o) {
  require(o.all != !o.name.empty(), "name", o.name.empty() ? "(missing)" : o.name,
          o.all ? "give a NAME or --all, not both" : "give a NAME (a sampler, measure, warp or integrand) or --all");
  require(!o.markdown || o.all, "markdown", "on", "--markdown writes the page of every entry: give --all");
  const std::vector<analysis::CatalogueEntry> entries =
      o.all ? analysis::catalogue_of(o.kind) : analysis::find_in_catalogue(o.name, o.kind);
  if (o.markdown) {
    fmt::print("{}", parameters_markdown(entries));
    return;
  }
  if (o.json) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& entry : entries)
      list.push_back({{"kind", entry.kind},
                      {"name", entry.name},
                      {"description", entry.description},
                      {"params", params_json(*entry.params)}});
    fmt::print("{}\n", list.dump(2));
    return;
  }
  for (const auto& entry : entries) {
    fmt::print("{} {}: {}\n", entry.kind, entry.name, entry.description);
    if (entry.params->empty()) fmt::print("  (no parameters)\n");
    for (const auto& param : *entry.params) fmt::print("  {}\n", analysis::describe_param(param));
  }
}
}  // namespace

void add_describe_command(CLI::App& app) {
  auto options = std::make_shared<DescribeOptions>();
  auto* command = app.add_subcommand(
      "describe", "Show the parameters of a sampler, measure, warp or integrand: type, range, default (the schema)");
  command->add_option("name", options->name, "the entry's name (e.g. poisson-disk, star, cone, genz-gaussian)");
  command->add_option("--kind", options->kind, "only this registry: sampler, measure, warp or integrand");
  command->add_flag("--all", options->all, "every entry");
  command->add_flag("--json", options->json, "print JSON");
  command->add_flag("--markdown", options->markdown, "with --all: the docs page docs/parameters.md");
  command->callback([options] { run_describe(*options); });
}

}  // namespace stratum::cli
