#pragma once
// Running one report section in a test: a staging folder, quick options and
// the section's context, shared by the section tests (tests/report/*).
#include <stdlib.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "report/sections.hpp"

namespace stratum::report::testing {

/// A temporary staging folder (with figures/) removed at the end of the test.
struct TempFolder {
  std::filesystem::path path;
  TempFolder() {
    std::string pattern = (std::filesystem::temp_directory_path() / "stratum-sections-XXXXXX").string();
    path = mkdtemp(pattern.data());
    std::filesystem::create_directory(path / "figures");
  }
  ~TempFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;
};

/// Runs section `id` in quick mode (seed 1, 2 threads) into `folder`, its
/// reference renders cached inside it; the figures are queued in `plots`.
/// Records a failure (and returns an empty Section) for an unknown id.
inline Section run_quick_section(const std::string& id, const TempFolder& folder, std::vector<plot::PlotJob>& plots,
                                 std::vector<std::string> extras = {}) {
  ReportOptions options;
  options.quick = true;
  options.seed = 1;
  options.threads = 2;
  options.extra_samplers = std::move(extras);
  options.cache_dir = (folder.path / "cache").string();
  const auto& all = report_sections();
  const auto info = std::find_if(all.begin(), all.end(), [&](const SectionInfo& s) { return s.id == id; });
  EXPECT_NE(info, all.end()) << id;
  if (info == all.end()) return {};
  SectionContext context(options, *info, folder.path, 2, plots);
  Section section = info->build(context);
  EXPECT_EQ(section.id, id);
  EXPECT_FALSE(section.text.empty());
  EXPECT_FALSE(section.tables.empty());
  EXPECT_FALSE(section.figures.empty());
  return section;
}

}  // namespace stratum::report::testing
