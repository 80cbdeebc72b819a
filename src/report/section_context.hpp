#pragma once
/// What a report section gets to work with: the options, where its figures
/// go, and the way to draw them. Figures are queued and drawn together at the
/// end (one Python process per core instead of one per figure).
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "stratum/analysis/convergence.hpp"
#include "stratum/plot.hpp"
#include "stratum/render/render.hpp"
#include "stratum/report/report.hpp"

namespace stratum::report {

class SectionContext {
 public:
  SectionContext(const ReportOptions& options, const SectionInfo& info, std::filesystem::path staging, unsigned threads,
                 std::vector<plot::PlotJob>& plots);

  bool quick() const { return options_.quick; }
  unsigned threads() const { return threads_; }  ///< resolved: ≥ 1
  std::uint64_t seed() const { return options_.seed; }
  const std::string& cache_dir() const { return options_.cache_dir; }
  const ReportOptions& options() const { return options_; }

  /// The --sampler extras, parsed ("name" or "name:randomizer").
  std::vector<analysis::SamplerChoice> extra_samplers() const;

  /// A new Section with id, lecture and title filled from the registry.
  Section start() const;

  /// Queues figure `name` (a file stem, unique within the section) drawn by
  /// plot script `script` (src/plot/scripts/<script>.py) from `data`;
  /// returns the Figure as the page will show it.
  Figure plot(std::string_view script, nlohmann::json data, const std::string& name, const std::string& caption);

  /// Writes a render as a tonemapped PNG figure now.
  Figure image(const render::Image& image, const std::string& name, const std::string& caption);

 private:
  std::string figure_file(const std::string& name) const;  ///< "figures/<section>-<name>.png"

  const ReportOptions& options_;
  const SectionInfo& info_;
  std::filesystem::path staging_;
  unsigned threads_;
  std::vector<plot::PlotJob>& plots_;
};

}  // namespace stratum::report
