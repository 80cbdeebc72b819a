/// The report's table of contents: one line per section, in the lecture's
/// order (LECTURE.md §1–13).
#include "sections.hpp"

namespace stratum::report {

const std::vector<SectionInfo>& report_sections() {
  static const std::vector<SectionInfo> sections{
      {"camera", "§1", "The camera integral: depth of field and motion blur", camera_section},
      {"variance", "§2", "Variance and its cost: 1 vs 16 shadow rays", variance_section},
      {"importance", "§3", "Importance sampling: light sampling, irradiance and the zero-variance case",
       importance_section},
      {"stratification", "§4", "Stratified sampling: convergence on an edge and a smooth integrand",
       stratification_section},
      {"disk-maps", "§5", "Sampling a disk: polar and concentric maps", disk_section},
      {"dimension", "§6", "High dimensions: quadrature against Monte Carlo", dimension_section},
      {"block-designs", "§7", "Block designs: Latin squares, N-rooks, N-queens, multi-jittered", block_designs_section},
      {"space-time", "§8", "Space-time patterns: Cook's pattern, magic squares and motion blur", space_time_section},
      {"path-tracing", "§9", "Path tracing: complete versus incomplete at equal ray count and at equal time",
       path_tracing_section},
      {"discrepancy", "§10", "Discrepancy: the local discrepancy, star and L2 values, Koksma–Hlawka",
       discrepancy_section},
      {"edge-discrepancy", "§10", "Edge discrepancy: antialiasing an edge with 1, 2, 4 or 8 samples on an 8×8 grid",
       edge_discrepancy_section},
      {"qmc", "§11", "Quasi-Monte Carlo: radical inverse, Hammersley and Halton", qmc_section},
      {"patterns", "§12", "Comparing patterns: Mitchell's random-edge discrepancy and spectra", patterns_section},
      {"four-views", "§13", "Four views of integration: spectrum, variance, discrepancy, quadrature",
       four_views_section},
  };
  return sections;
}

const std::vector<LectureTopic>& lecture_topics() {
  static const std::vector<LectureTopic> topics{
      {"§1", "The camera integral"},
      {"§2", "Variance and its cost"},
      {"§3", "Importance sampling"},
      {"§4", "Stratified sampling"},
      {"§5", "Sampling a disk"},
      {"§6", "High dimensions"},
      {"§7", "Block designs"},
      {"§8", "Space-time patterns"},
      {"§9", "Path tracing: complete versus incomplete"},
      {"§10", "Discrepancy (and Mitchell's edge discrepancy, SGI's 8×8 multisampling grid)"},
      {"§11", "Quasi-Monte Carlo patterns"},
      {"§12", "Comparing patterns"},
      {"§13", "Four views of integration"},
  };
  return topics;
}

}  // namespace stratum::report
