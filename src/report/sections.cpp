/// The report's table of contents: one line per section, in the lecture's
/// order (LECTURE.md §1–13).
#include "sections.hpp"

namespace stratum::report {

const std::vector<SectionInfo>& report_sections() {
  static const std::vector<SectionInfo> sections{
      {"disk-maps", "§5", "Sampling a disk: polar and concentric maps", disk_section},
  };
  return sections;
}

}  // namespace stratum::report
