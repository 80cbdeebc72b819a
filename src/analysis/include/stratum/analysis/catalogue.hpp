#pragma once
/// Every registry entry that takes parameters (samplers, measures, warps,
/// integrands) with its schema, in one list: what `stratum describe`,
/// Python's `stratum.describe` and the docs' parameter tables are made of.
#include <string>
#include <string_view>
#include <vector>

#include "stratum/registry/params.hpp"

namespace stratum::analysis {

struct CatalogueEntry {
  std::string kind;  ///< "sampler", "measure", "warp" or "integrand"
  std::string name;
  std::string description;
  const std::vector<Param>* params = nullptr;  ///< the registry's own schema (static lifetime)
};

/// Samplers, then measures, warps and integrands, each in registry order.
const std::vector<CatalogueEntry>& catalogue();

/// The entries of one kind ("sampler", "measure", "warp", "integrand"; empty:
/// all); throws invalid_argument for another kind.
std::vector<CatalogueEntry> catalogue_of(std::string_view kind);

/// The entries called `name` (a name may exist in two registries: a warp and
/// an integrand, say), restricted to `kind` unless it is empty; throws
/// invalid_argument listing the known names when there is none.
std::vector<CatalogueEntry> find_in_catalogue(std::string_view name, std::string_view kind = {});

/// One line per parameter: "name: integer in [1, 100000], default 30 -- description".
std::string describe_param(const Param& param);

}  // namespace stratum::analysis
