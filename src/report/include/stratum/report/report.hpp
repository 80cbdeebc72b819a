#pragma once
/// `stratum report`: the lecture (LECTURE.md §1–13) reproduced as one
/// self-contained HTML page. Each section runs the library on this machine,
/// draws its figures with matplotlib and writes the measurements behind them;
/// no number in the page is typed in. The page and its figures are written
/// into a staging folder and moved into place only when every section has
/// succeeded, so a failed run never leaves a page that looks complete.
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace stratum::report {

struct ReportOptions {
  std::string directory = "report";  ///< where index.html, report.json and figures/ go
  bool quick = false;                ///< smaller N, runs and spp; same sections and figures (≤ 1 minute)
  /// Extra registry samplers ("name" or "name:randomizer") added to every
  /// comparison of patterns (stratification, discrepancy, the four views).
  std::vector<std::string> extra_samplers;
  std::vector<std::string> only;             ///< section ids to run (empty: every section)
  unsigned threads = 0;                      ///< 0: every core
  std::uint64_t seed = 0;                    ///< stratum::default_seed
  std::string cache_dir = ".stratum-cache";  ///< converged reference renders, reused across runs
};

/// A figure: a PNG file relative to the report folder ("figures/…").
struct Figure {
  std::string file;
  std::string caption;
};

/// A table of measured values, already formatted as text.
struct Table {
  std::string caption;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  /// An anchor for links to it ("table-<id>" on the page), where a lecture
  /// slide points to it (lecture_slides()); empty: none.
  std::string id = {};
};

/// One section of the page, as built by its section function.
struct Section {
  std::string id;       ///< stable anchor, e.g. "variance"
  std::string lecture;  ///< "§2"
  std::string title;
  /// What the section shows, in a few sentences holding the measured
  /// numbers (formatted from this run, never typed in).
  std::vector<std::string> text;
  std::vector<Figure> figures;
  std::vector<Table> tables;
  /// "Try it": commands (and Python calls) that reproduce the section's
  /// measurement with other samplers, shown at the end of the section.
  std::vector<std::string> try_it;
  nlohmann::json numbers = nlohmann::json::object();  ///< the measurements, written to report.json
  double seconds = 0;                                 ///< wall time of the section
};

class SectionContext;  // src/report/section_context.hpp

/// A section of the report: its id, the lecture section it reproduces and
/// the function that runs it.
struct SectionInfo {
  std::string id;
  std::string lecture;
  std::string title;
  Section (*build)(SectionContext&);
};

/// Every section, in the lecture's order.
const std::vector<SectionInfo>& report_sections();

/// A slide of the lecture as LECTURE.md states it, its formula where it
/// states one, and where the report reproduces it: a section and an anchor
/// in that section ("figure-<file stem>", "table-<Table::id>"; empty: the
/// section as a whole). The page's index lists them, and each section shows
/// the formulas of its slides under its heading.
struct LectureSlide {
  std::string lecture;  ///< "§2"
  std::string title;    ///< "Soft shadows: 1 shadow ray per eye ray versus 16"
  std::string formula;  ///< "V[mean of N] = V[Y]/N" (Unicode); empty: none on the slide
  std::string section;  ///< a report_sections() id
  std::string anchor;   ///< "figure-variance-shadow-rays"
};

/// Every slide, in the lecture's order (lecture_slides.cpp).
const std::vector<LectureSlide>& lecture_slides();

/// Checks every option before any work: the folder can be created and
/// written, every extra sampler exists (with its randomizer) and takes 2D
/// points, every `only` id is a section. Throws stratum::invalid_argument
/// naming the option, its value and what is allowed.
void validate_report_options(const ReportOptions& options);

struct ReportResult {
  std::string index;  ///< path of the written index.html
  std::vector<Section> sections;
  double seconds = 0;
};

/// Validates, runs every (selected) section and writes DIR/index.html,
/// DIR/report.json and DIR/figures/. `progress` receives one line per
/// section started and finished.
ReportResult write_report(const ReportOptions& options, const std::function<void(const std::string&)>& progress = {});

/// The HTML page for `sections` (self-contained: inline CSS, figures by
/// relative path, no script, no network).
std::string report_html(const std::vector<Section>& sections, const ReportOptions& options, double seconds);

}  // namespace stratum::report
