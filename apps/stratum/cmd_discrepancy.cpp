/// `stratum discrepancy`: any registry measure (or all those defined for the
/// points' dimension) of a point file or of a sampler's points, as text or JSON.
#include <fmt/core.h>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "point_input.hpp"
#include "stratum/analysis/catalogue.hpp"
#include "stratum/analysis/measures.hpp"
#include "stratum/registry.hpp"
#include "stratum/util/error.hpp"

namespace stratum::cli {

namespace {
namespace sa = stratum::analysis;

struct DiscrepancyOptions : PointInput {
  std::string measure;
  std::vector<std::string> measure_params;
  bool json = false;
};

nlohmann::json result_json(const std::string& name, const sa::MeasureResult& r) {
  nlohmann::json out = {{"name", name}, {"kind", r.kind}, {"value", r.value}, {"extras", r.extras}};
  out["lower"] = r.lower ? nlohmann::json(*r.lower) : nlohmann::json(nullptr);
  out["upper"] = r.upper ? nlohmann::json(*r.upper) : nlohmann::json(nullptr);
  return out;
}

std::string result_text(const std::string& name, const sa::MeasureResult& r) {
  std::string extras;
  for (const auto& [key, value] : r.extras) extras += fmt::format("; {} = {}", key, value);
  if (r.kind == "bounds")
    return fmt::format("{:<16} in [{}, {}] (bounds: the exact value lies between them{})", name,
                       r.lower.value_or(r.value), r.upper.value_or(r.value), extras);
  return fmt::format("{:<16} {} ({}{})", name, r.value, r.kind, extras);
}

void run_discrepancy(const DiscrepancyOptions& o) {
  std::map<std::string, std::string> params;
  for (const auto& item : o.measure_params) {
    auto [key, value] = parse_key_value("measure-param", item);
    params[key] = value;
  }
  if (o.measure != "all") sa::find_measure(o.measure);  // an unknown name fails before any work
  if (o.file.empty() && o.n && *o.n >= 1 &&
      o.d.value_or(2) >= 1) {  // generated points: their memory and the measure's, first
    const auto n = static_cast<std::size_t>(*o.n), d = static_cast<std::size_t>(o.d.value_or(2));
    for (const auto& m : sa::measures())
      if (m.name == o.measure || (o.measure == "all" && d >= m.min_dim && (m.max_dim == 0 || d <= m.max_dim)))
        sa::require_measure_memory(m.name, n, d, {params, static_cast<unsigned>(o.threads)});
  }
  const PointSet points = load_points(o);
  const sa::PointView view{points.data.get(), points.n, points.d};
  sa::check_unit_cube(view);

  std::vector<std::pair<std::string, sa::MeasureResult>> results;
  std::vector<std::pair<std::string, std::string>> skipped;
  if (o.measure != "all") {
    results.emplace_back(o.measure, sa::compute_measure(o.measure, view, {params, static_cast<unsigned>(o.threads)}));
  } else {
    for (const auto& [key, value] : params) {  // every --measure-param must belong to some measure
      bool used = false;
      for (const auto& m : sa::measures())
        for (const auto& spec : m.params) used = used || spec.name == key;
      if (!used) throw invalid_argument("measure-param", key, "no measure takes it (see `stratum discrepancy --help`)");
    }
    for (const auto& m : sa::measures()) {
      if (view.d < m.min_dim || (m.max_dim != 0 && view.d > m.max_dim)) continue;  // not defined for this d
      sa::MeasureRequest request{{}, static_cast<unsigned>(o.threads)};
      for (const auto& spec : m.params)
        if (params.count(spec.name)) request.params[spec.name] = params.at(spec.name);
      try {
        results.emplace_back(m.name, sa::compute_measure(m.name, view, request));
      } catch (const invalid_argument& error) {  // e.g. an exact method's size limit
        skipped.emplace_back(m.name, error.what());
      }
    }
  }

  if (o.json) {
    nlohmann::json list = nlohmann::json::array(), skips = nlohmann::json::array();
    for (const auto& [name, r] : results) list.push_back(result_json(name, r));
    for (const auto& [name, why] : skipped) skips.push_back({{"name", name}, {"reason", why}});
    const std::string source = o.file.empty() ? "sampler " + o.sampler : o.file;
    fmt::print(
        "{}\n",
        nlohmann::json{{"source", source}, {"n", points.n}, {"d", points.d}, {"measures", list}, {"skipped", skips}}
            .dump(2));
    return;
  }
  for (const auto& [name, r] : results) fmt::print("{}\n", result_text(name, r));
  for (const auto& [name, why] : skipped) fmt::print("{:<16} skipped: {}\n", name, why);
}

std::string measure_help() {
  std::string text = "measure name, or `all` (every measure defined for the points' d):";
  for (const auto& m : sa::measures()) {
    text += fmt::format("\n  {:<16} {}", m.name, m.description);
    for (const auto& p : m.params) text += fmt::format("\n  {:<18} --measure-param {}", "", sa::describe_param(p));
  }
  return text;
}
}  // namespace

void add_discrepancy_command(CLI::App& app) {
  auto o = std::make_shared<DiscrepancyOptions>();
  auto* command = app.add_subcommand("discrepancy", "Measure a point set: discrepancies, stratification, geometry");
  add_point_input_options(*command, *o);
  command->add_option("-m,--measure", o->measure, measure_help())->required();
  command->add_option("--measure-param", o->measure_params, "measure parameter KEY=VALUE (repeatable)");
  add_threads_option(*command, o->threads, "threads (results do not depend on it)");
  command->add_flag("--json", o->json, "print JSON");
  command->callback([o] { run_discrepancy(*o); });
}

}  // namespace stratum::cli
