#pragma once
/// Figures for every face: matplotlib scripts (src/plot/scripts/*.py,
/// embedded at build time) run by Debian's Python on a JSON file.
#include <nlohmann/json.hpp>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace stratum::io {
class OutputFile;
}

namespace stratum::plot {

/// Runs plot script `script` (src/plot/scripts/<script>.py) as
/// `python3 SCRIPT DATA.json OUT.png` into the staging file of an
/// io::OutputFile, put in place only when complete, so a failed plot leaves
/// no file (docs/outputs.md). The interpreter is $STRATUM_PYTHON or
/// /usr/bin/python3. Throws invalid_argument when `png` cannot be written
/// and std::runtime_error when the script fails.
void write_plot(std::string_view script, const nlohmann::json& data, const std::string& png);
/// The same into an output prepared before the command's work (prepare_plot).
void write_plot(std::string_view script, const nlohmann::json& data, io::OutputFile& png);

/// The figure output of option `argument`, checked and staged now (null for
/// an empty path): a bad --plot path is found before the work, not after it.
std::unique_ptr<io::OutputFile> prepare_plot(const std::string& argument, const std::string& png);

/// One figure to draw: plot script, its data, the PNG to write.
struct PlotJob {
  std::string script;
  nlohmann::json data;
  std::string png;
  io::OutputFile* output = nullptr;  ///< a prepared output for `png`, or null (one is made)
};

/// Draws every job in up to `processes` Python processes (matplotlib is
/// imported once per process, not once per figure). Each figure is renamed
/// into place only when every job succeeded; otherwise throws
/// std::runtime_error naming the script that failed, and writes none.
void write_plots(const std::vector<PlotJob>& jobs, unsigned processes);

}  // namespace stratum::plot
