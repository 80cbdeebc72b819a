// The report's frame: option checks, the page's HTML, number formatting and
// the staging folder (the sections have their own tests).
#include "stratum/report/report.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
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
  section.id = "path-tracing";
  section.lecture = "§9";
  section.title = "A <b> & \"c\"";
  section.text = {"1 < 2"};
  section.figures = {{"figures/path-tracing-complete-incomplete.png", "caption <i>"}};
  section.tables = {{"t", {"h"}, {{"<td>"}}}};
  const std::string html = stratum::report::report_html({section}, ReportOptions{}, 1.0);
  EXPECT_NE(html.find("A &lt;b&gt; &amp; &quot;c&quot;"), std::string::npos);
  EXPECT_NE(html.find("<p>1 &lt; 2</p>"), std::string::npos);
  EXPECT_NE(html.find("<img src=\"figures/path-tracing-complete-incomplete.png\""), std::string::npos);
  EXPECT_NE(html.find("<td>&lt;td&gt;</td>"), std::string::npos);
  EXPECT_NE(html.find("href=\"#path-tracing\""), std::string::npos);
  EXPECT_EQ(html.find("<b>"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);  // nothing to run, nothing fetched
}

TEST(LectureSlides, EverySlideNamesASectionOfItsLectureAndAnAnchorOfThatSection) {
  const auto& sections = stratum::report::report_sections();
  for (const auto& slide : stratum::report::lecture_slides()) {
    const auto section =
        std::find_if(sections.begin(), sections.end(), [&](const auto& info) { return info.id == slide.section; });
    ASSERT_NE(section, sections.end()) << slide.title << ": no section " << slide.section;
    EXPECT_EQ(section->lecture, slide.lecture) << slide.title;
    EXPECT_FALSE(slide.title.empty());
    const bool own_figure = slide.anchor.rfind("figure-" + slide.section + "-", 0) == 0;
    EXPECT_TRUE(slide.anchor.empty() || own_figure || slide.anchor.rfind("table-", 0) == 0) << slide.anchor;
  }
}

TEST(LectureSlides, EveryTopicHasSlidesAndEverySectionAFormula) {
  const auto& slides = stratum::report::lecture_slides();
  for (const auto& topic : stratum::report::lecture_topics())
    EXPECT_TRUE(std::any_of(slides.begin(), slides.end(), [&](const auto& s) { return s.lecture == topic.lecture; }))
        << topic.lecture;
  for (const auto& section : stratum::report::report_sections())
    EXPECT_TRUE(std::any_of(slides.begin(), slides.end(),
                            [&](const auto& s) { return s.section == section.id && !s.formula.empty(); }))
        << section.id << " shows no formula of the lecture";
}

TEST(LectureSlides, TheIndexLinksASlideToItsFigureOrTableOnlyWhereTheRunHasIt) {
  using stratum::report::Section;
  Section qmc;
  qmc.id = "qmc";
  qmc.lecture = "§11";
  qmc.title = "QMC";
  qmc.tables = {{"φ2", {"i"}, {}, "radical-inverse"}};  // the radical-inverse table, but no star-vs-n figure
  const auto located = stratum::report::locate_slides({qmc});
  for (const auto& at : located) {
    EXPECT_EQ(at.section != nullptr, at.slide->section == "qmc") << at.slide->title;
    if (at.slide->anchor == "table-radical-inverse") {
      EXPECT_TRUE(at.found);
    }
    if (at.slide->anchor == "figure-qmc-star-vs-n") {
      EXPECT_FALSE(at.found);
    }
  }
  const std::string html = stratum::report::report_html({qmc}, ReportOptions{}, 1.0);
  EXPECT_NE(html.find("href=\"#table-radical-inverse\""), std::string::npos);
  EXPECT_NE(html.find("id=\"table-radical-inverse\""), std::string::npos);
  EXPECT_EQ(html.find("href=\"#figure-qmc-star-vs-n\""), std::string::npos);      // not drawn: no dangling link
  EXPECT_NE(html.find("(not run: see <code>--only</code>)"), std::string::npos);  // the other sections
  // The section shows its slides' formulas under its heading.
  const auto heading = html.find("<section id=\"qmc\">");
  ASSERT_NE(heading, std::string::npos);
  EXPECT_NE(html.find("<dd class=\"formula\">i = Σ d<sub>k</sub> b<sup>k</sup> ⇒ φ<sub>b</sub>(i) = Σ d<sub>k</sub> "
                      "b<sup>−k−1</sup>",
                      heading),
            std::string::npos);
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
  // Rounding up to a power of ten keeps the significant digits: 0.99996 is
  // 1.00 (not 1.000), 9.9996 is 10.0, 0.0099996 is 0.0100.
  EXPECT_EQ(format_number(0.99996), "1.00");
  EXPECT_EQ(format_number(-0.99996), "-1.00");
  EXPECT_EQ(format_number(9.9996), "10.0");
  EXPECT_EQ(format_number(0.0099996), "0.0100");
  EXPECT_EQ(format_number(0.9994), "0.999");
}

TEST(ReportFormat, AnEstimateAndItsIntervalPrintedAlike) {
  using stratum::report::format_alike;
  // The estimate's decimals for all three (never "1.000 (1.000–1.00)").
  auto text = format_alike(0.99996, 0.99991, 1.00002);
  EXPECT_EQ(text.estimate, "1.00");
  EXPECT_EQ(text.low, "1.00");
  EXPECT_EQ(text.high, "1.00");
  text = format_alike(1.0004, 0.981, 1.0203);
  EXPECT_EQ(text.estimate, "1.00");
  EXPECT_EQ(text.low, "0.98");
  EXPECT_EQ(text.high, "1.02");
  text = format_alike(-1.5123, -1.61, -1.4149);
  EXPECT_EQ(text.estimate, "-1.51");
  EXPECT_EQ(text.low, "-1.61");
  EXPECT_EQ(text.high, "-1.41");
  // More decimals where a bound would keep fewer than two significant digits.
  text = format_alike(5.0, 0.0456, 55.1);
  EXPECT_EQ(text.estimate, "5.000");
  EXPECT_EQ(text.low, "0.046");
  EXPECT_EQ(text.high, "55.100");
  // Outside the fixed range each is its own: 3 significant digits.
  text = format_alike(2.5e-5, 2.04e-5, 3.1e-5);
  EXPECT_EQ(text.estimate, "2.50e-05");
  EXPECT_EQ(text.low, "2.04e-05");
  EXPECT_EQ(text.high, "3.10e-05");
  text = format_alike(2.0, 1.0, std::numeric_limits<double>::infinity());
  EXPECT_EQ(text.high, "∞");
  EXPECT_EQ(text.estimate, "2.00");
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
