#pragma once
/// Figures for every face: matplotlib scripts (src/plot/scripts/*.py,
/// embedded at build time) run by Debian's Python on a JSON file.
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace stratum::plot {

/// Runs plot script `script` (src/plot/scripts/<script>.py) as
/// `python3 SCRIPT DATA.json OUT.png`, then renames the figure onto `png`, so
/// a failed plot leaves no file. The interpreter is $STRATUM_PYTHON or
/// /usr/bin/python3. Throws invalid_argument when `png` cannot be written
/// and std::runtime_error when the script fails.
void write_plot(std::string_view script, const nlohmann::json& data, const std::string& png);

/// One figure to draw: plot script, its data, the PNG to write.
struct PlotJob {
  std::string script;
  nlohmann::json data;
  std::string png;
};

/// Draws every job in up to `processes` Python processes (matplotlib is
/// imported once per process, not once per figure). Each figure is renamed
/// into place only when every job succeeded; otherwise throws
/// std::runtime_error naming the script that failed, and writes none.
void write_plots(const std::vector<PlotJob>& jobs, unsigned processes);

}  // namespace stratum::plot
