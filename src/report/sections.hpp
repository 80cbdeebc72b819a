#pragma once
/// The report's section functions, one file each (src/report/section_*.cpp),
/// listed in lecture order by report_sections() (sections.cpp).
#include "section_context.hpp"

namespace stratum::report {

Section camera_section(SectionContext& context);            // §1  section_camera.cpp
Section variance_section(SectionContext& context);          // §2  section_variance.cpp
Section importance_section(SectionContext& context);        // §3  section_importance.cpp
Section stratification_section(SectionContext& context);    // §4  section_stratification.cpp
Section disk_section(SectionContext& context);              // §5  section_disk.cpp
Section dimension_section(SectionContext& context);         // §6  section_dimension.cpp
Section block_designs_section(SectionContext& context);     // §7  section_block_designs.cpp
Section space_time_section(SectionContext& context);        // §8  section_space_time.cpp
Section path_tracing_section(SectionContext& context);      // §9  section_path_tracing.cpp
Section discrepancy_section(SectionContext& context);       // §10 section_discrepancy.cpp
Section edge_discrepancy_section(SectionContext& context);  // §10 section_edge_discrepancy.cpp
Section qmc_section(SectionContext& context);               // §11 section_qmc.cpp
Section patterns_section(SectionContext& context);          // §12 section_patterns.cpp
Section four_views_section(SectionContext& context);        // §13 section_four_views.cpp

/// Formats a number for the page: `digits` significant digits, no
/// exponent between 1e-3 and 1e6.
std::string format_number(double value, int digits = 3);

/// An estimate and its interval's bounds, printed alike: with the decimals
/// that give the estimate `digits` significant digits (more where a bound
/// would keep fewer than two), so that the three line up ("1.00 (0.98–1.02)");
/// each by format_number where one lies outside its fixed-notation range.
struct FormattedInterval {
  std::string estimate, low, high;
};
FormattedInterval format_alike(double estimate, double low, double high, int digits = 3);

// Words for the page (names.cpp).

/// "sobol:owen" (or "sobol" when no randomizer is given).
std::string sampler_spec(const std::string& sampler, const std::string& randomize);
std::string sampler_spec(const analysis::SamplerChoice& choice);
/// The name a reader knows: "Owen-scrambled Sobol'", "Zaremba with
/// Cranley–Patterson rotation", "random" (an empty randomizer is the
/// registry's default).
std::string sampler_name(const std::string& sampler, const std::string& randomize);
std::string sampler_name(const analysis::SamplerChoice& choice);
/// The name followed by its spec as inline code: "Owen-scrambled Sobol' `sobol:owen`"
/// (the page shows text between backticks as a small code tag).
std::string named_with_spec(const analysis::SamplerChoice& choice);
/// The first letter in upper case (for a name that starts a sentence or a cell).
std::string capitalized(std::string text);
/// "1 point", "16 points" (plural: singular + "s" unless given).
std::string counted(std::uint64_t count, const std::string& singular, const std::string& plural = "");
/// "340 ms", "2.31 s", "under 1 ms": never "0.0 s".
std::string format_seconds(double seconds);

/// E[A(1 − A)] over random lines hitting the unit square (the
/// motion-invariant measure of Mitchell's random edges; A the area cut off):
/// N·E[D²] of N independent uniform points (section_patterns.cpp).
double expected_binomial_edge_variance(int steps);

/// A lecture topic (LECTURE.md) and its title as the lecture gives it.
struct LectureTopic {
  std::string lecture;  ///< "§10"
  std::string title;
};

/// The lecture's 13 topics in order, for the index at the top of the page.
const std::vector<LectureTopic>& lecture_topics();

/// A figure's anchor on the page: "figure-" and its file's stem
/// ("figures/variance-shadow-rays.png" → "figure-variance-shadow-rays").
std::string figure_anchor(const Figure& figure);

/// Where a slide is reproduced in a run: its section (null when the run
/// left it out) and whether that section holds the slide's anchor.
struct SlideLocation {
  const LectureSlide* slide = nullptr;
  const Section* section = nullptr;
  bool found = false;
};
/// Every lecture slide, located among `sections`.
std::vector<SlideLocation> locate_slides(const std::vector<Section>& sections);

}  // namespace stratum::report
