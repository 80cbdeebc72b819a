#pragma once
/// The parameter schema as JSON and as the docs' Markdown tables: one
/// rendering for `stratum describe`, `stratum samplers --json`,
/// `integrate --list --json` and docs/parameters.md.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "stratum/analysis/catalogue.hpp"
#include "stratum/registry/params.hpp"

namespace stratum::cli {

/// {"name", "type", "description", "default" (null: none), "range" (null:
/// unbounded; infinite ends null), "choices", "length", "separator"}.
nlohmann::json param_json(const Param& param);
nlohmann::json params_json(const std::vector<Param>& params);

/// docs/parameters.md: one table per registry kind, a row per parameter.
std::string parameters_markdown(const std::vector<analysis::CatalogueEntry>& entries);

}  // namespace stratum::cli
