#pragma once
/// The report's section functions, one file each (src/report/section_*.cpp),
/// listed in lecture order by report_sections() (sections.cpp).
#include "section_context.hpp"

namespace stratum::report {

Section camera_section(SectionContext& context);          // §1  section_camera.cpp
Section variance_section(SectionContext& context);        // §2  section_variance.cpp
Section importance_section(SectionContext& context);      // §3  section_importance.cpp
Section stratification_section(SectionContext& context);  // §4  section_stratification.cpp
Section disk_section(SectionContext& context);            // §5  section_disk.cpp
Section dimension_section(SectionContext& context);       // §6  section_dimension.cpp
Section block_designs_section(SectionContext& context);   // §7  section_block_designs.cpp
Section space_time_section(SectionContext& context);      // §8  section_space_time.cpp
Section path_tracing_section(SectionContext& context);    // §9  section_path_tracing.cpp
Section discrepancy_section(SectionContext& context);     // §10 section_discrepancy.cpp
Section qmc_section(SectionContext& context);             // §11 section_qmc.cpp
Section patterns_section(SectionContext& context);        // §12 section_patterns.cpp
Section four_views_section(SectionContext& context);      // §13 section_four_views.cpp

/// Formats a number for the page: `digits` significant digits, no
/// exponent between 1e-3 and 1e6.
std::string format_number(double value, int digits = 3);

}  // namespace stratum::report
