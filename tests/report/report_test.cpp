// The report's frame: option checks, the page's HTML, number formatting and
// the staging folder (the sections have their own tests).
#include "stratum/report/report.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "report/sections.hpp"
#include "stratum/util/error.hpp"

namespace {

using stratum::report::ReportOptions;
namespace fs = std::filesystem;

std::string read(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

fs::path scratch(const std::string& name) {
  const fs::path path = fs::temp_directory_path() / ("stratum-report-test-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(path);
  return path;
}

TEST(ReportOptions, RejectsUnknownSamplersSectionsAndThreadsBeforeAnyWork) {
  ReportOptions options;
  options.directory = scratch("bad").string();
  options.extra_samplers = {"no-such"};
  EXPECT_THROW(stratum::report::validate_report_options(options), stratum::invalid_argument);
  options.extra_samplers = {"sobol:no-such-randomizer"};
  EXPECT_THROW(stratum::report::validate_report_options(options), stratum::invalid_argument);
  options.extra_samplers = {"sobol:owen", "jittered"};
  EXPECT_NO_THROW(stratum::report::validate_report_options(options));
  options.only = {"nope"};
  EXPECT_THROW(stratum::report::write_report(options), stratum::invalid_argument);
  EXPECT_FALSE(fs::exists(options.directory));
  options.only.clear();
  options.threads = 5000;
  EXPECT_THROW(stratum::report::validate_report_options(options), stratum::invalid_argument);
}

TEST(ReportHtml, EscapesTextAndListsEverySection) {
  stratum::report::Section section;
  section.id = "x";
  section.lecture = "§9";
  section.title = "A <b> & \"c\"";
  section.text = {"1 < 2"};
  section.figures = {{"figures/x-a.png", "caption <i>"}};
  section.tables = {{"t", {"h"}, {{"<td>"}}}};
  const std::string html = stratum::report::report_html({section}, ReportOptions{}, 1.0);
  EXPECT_NE(html.find("A &lt;b&gt; &amp; &quot;c&quot;"), std::string::npos);
  EXPECT_NE(html.find("<p>1 &lt; 2</p>"), std::string::npos);
  EXPECT_NE(html.find("<img src=\"figures/x-a.png\""), std::string::npos);
  EXPECT_NE(html.find("<td>&lt;td&gt;</td>"), std::string::npos);
  EXPECT_NE(html.find("href=\"#x\""), std::string::npos);
  EXPECT_EQ(html.find("<b>"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);  // nothing to run, nothing fetched
}

TEST(ReportFormat, SignificantDigitsAndExponents) {
  using stratum::report::format_number;
  EXPECT_EQ(format_number(1.23456), "1.23");
  EXPECT_EQ(format_number(123.456), "123");
  EXPECT_EQ(format_number(0.0123456), "0.0123");
  EXPECT_EQ(format_number(1.5e-5), "1.50e-05");
  EXPECT_EQ(format_number(2.5e7, 2), "2.5e+07");
  EXPECT_EQ(format_number(0.0), "0.00");
  EXPECT_EQ(format_number(-2.0 / 3.0), "-0.667");
  EXPECT_EQ(format_number(std::nan("")), "n/a");
}

TEST(WriteReport, OneSectionIntoPlaceAndNoStagingLeft) {
  ReportOptions options;
  options.directory = scratch("one").string();
  options.quick = true;
  options.only = {"disk-maps"};
  options.threads = 1;
  const auto result = stratum::report::write_report(options);
  ASSERT_EQ(result.sections.size(), 1u);
  EXPECT_EQ(result.index, (fs::path(options.directory) / "index.html").string());
  const std::string page = read(result.index);
  for (const auto& figure : result.sections[0].figures) {
    EXPECT_TRUE(fs::is_regular_file(fs::path(options.directory) / figure.file)) << figure.file;
    EXPECT_NE(page.find(figure.file), std::string::npos);
  }
  EXPECT_TRUE(fs::is_regular_file(fs::path(options.directory) / "report.json"));
  for (const auto& entry : fs::directory_iterator(options.directory))
    EXPECT_EQ(entry.path().filename().string().find(".stratum-tmp."), std::string::npos) << entry.path();
  fs::remove_all(options.directory);
}

}  // namespace
