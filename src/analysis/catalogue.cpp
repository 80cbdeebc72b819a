#include "stratum/analysis/catalogue.hpp"

#include <algorithm>
#include <limits>

#include "stratum/analysis/integrands.hpp"
#include "stratum/analysis/measures.hpp"
#include "stratum/registry.hpp"
#include "stratum/util/error.hpp"
#include "stratum/warp_registry.hpp"

namespace stratum::analysis {

const std::vector<CatalogueEntry>& catalogue() {
  static const std::vector<CatalogueEntry> entries = [] {
    std::vector<CatalogueEntry> list;
    for (const auto& s : samplers()) list.push_back({"sampler", s.name, s.description, &s.params});
    for (const auto& m : measures()) list.push_back({"measure", m.name, m.description, &m.params});
    for (const auto& w : warps()) list.push_back({"warp", w.name, w.description, &w.params});
    for (const auto& i : integrands()) list.push_back({"integrand", i.name, i.description, &i.params});
    return list;
  }();
  return entries;
}

std::vector<CatalogueEntry> catalogue_of(std::string_view kind) {
  static const std::vector<std::string> kinds = {"sampler", "measure", "warp", "integrand"};
  if (!kind.empty() && std::find(kinds.begin(), kinds.end(), kind) == kinds.end())
    throw invalid_argument("kind", kind, "must be sampler, measure, warp or integrand");
  std::vector<CatalogueEntry> entries;
  for (const auto& entry : catalogue())
    if (kind.empty() || entry.kind == kind) entries.push_back(entry);
  return entries;
}

std::vector<CatalogueEntry> find_in_catalogue(std::string_view name, std::string_view kind) {
  const std::vector<CatalogueEntry> candidates = catalogue_of(kind);
  std::vector<CatalogueEntry> found;
  for (const auto& entry : candidates)
    if (entry.name == name) found.push_back(entry);
  if (found.empty()) {
    std::string names;
    for (const auto& entry : candidates) names += (names.empty() ? "" : ", ") + entry.name;
    throw invalid_argument("name", name.empty() ? "''" : std::string(name),
                           "no " +
                               (kind.empty() ? std::string("sampler, measure, warp or integrand") : std::string(kind)) +
                               " is called that; known: " + names);
  }
  return found;
}

std::string describe_param(const Param& param) {
  std::string text = param.name + ": " + std::string(type_name(param.type));
  const std::string range = range_text(param.range);
  const bool numeric = param.type == ParamType::integer || param.type == ParamType::real ||
                       param.type == ParamType::integers || param.type == ParamType::reals;
  if (numeric && !range.empty()) text += " in " + range;
  if (param.type == ParamType::choice) {
    std::string choices;
    for (const auto& c : param.choices) choices += (choices.empty() ? "" : "|") + c;
    text += " " + choices;
  }
  if (param.type == ParamType::integers || param.type == ParamType::reals) {
    const Length& length = param.length;
    const std::string count = length.min == length.max ? std::to_string(length.min)
                              : length.max == std::numeric_limits<std::size_t>::max()
                                  ? std::to_string(length.min) + "+"
                                  : std::to_string(length.min) + "-" + std::to_string(length.max);
    text += ", " + count + " separated by '" + std::string(1, param.separator) + "'";
  }
  text += param.default_value.empty() ? ", no default" : ", default " + param.default_value;
  return text + " -- " + param.description;
}

}  // namespace stratum::analysis
