/// The report page: plain HTML with inline CSS, figures by relative path,
/// no script and nothing fetched from a network, so it opens from disk.
#include <fmt/format.h>

#include <cmath>
#include <string>

#include "sections.hpp"

namespace stratum::report {

namespace {

std::string escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

constexpr const char* style = R"css(
body { font-family: sans-serif; max-width: 1100px; margin: 2em auto; padding: 0 1em; color: #222; line-height: 1.45; }
h1 { margin-bottom: 0.2em; } h2 { border-bottom: 1px solid #ccc; padding-bottom: 0.2em; margin-top: 2em; }
.meta, figcaption, .time { color: #666; font-size: 0.9em; }
.figures { display: flex; flex-wrap: wrap; gap: 1em; }
figure { margin: 0; max-width: 100%; } figure img { max-width: 100%; height: auto; border: 1px solid #eee; }
table { border-collapse: collapse; margin: 1em 0; font-size: 0.92em; }
th, td { border: 1px solid #ccc; padding: 0.25em 0.6em; text-align: right; }
th { background: #f4f4f4; } td:first-child, th:first-child { text-align: left; }
caption { caption-side: top; text-align: left; font-weight: bold; padding-bottom: 0.3em; }
nav ol { columns: 2; }
)css";

std::string table_html(const Table& table) {
  std::string html = "<table>\n";
  if (!table.caption.empty()) html += "<caption>" + escape(table.caption) + "</caption>\n";
  html += "<tr>";
  for (const auto& cell : table.header) html += "<th>" + escape(cell) + "</th>";
  html += "</tr>\n";
  for (const auto& row : table.rows) {
    html += "<tr>";
    for (const auto& cell : row) html += "<td>" + escape(cell) + "</td>";
    html += "</tr>\n";
  }
  return html + "</table>\n";
}

std::string section_html(const Section& section) {
  std::string html = fmt::format("<section id=\"{}\">\n<h2>{} {}</h2>\n", escape(section.id), escape(section.lecture),
                                 escape(section.title));
  for (const auto& paragraph : section.text) html += "<p>" + escape(paragraph) + "</p>\n";
  if (!section.figures.empty()) {
    html += "<div class=\"figures\">\n";
    for (const auto& figure : section.figures)
      html += fmt::format("<figure><img src=\"{}\" alt=\"{}\"><figcaption>{}</figcaption></figure>\n",
                          escape(figure.file), escape(figure.caption), escape(figure.caption));
    html += "</div>\n";
  }
  for (const auto& table : section.tables) html += table_html(table);
  html += fmt::format("<p class=\"time\">Computed in {:.1f} s.</p>\n</section>\n", section.seconds);
  return html;
}

}  // namespace

std::string format_number(double value, int digits) {
  if (!std::isfinite(value)) return std::isnan(value) ? "n/a" : (value > 0 ? "∞" : "−∞");
  const double magnitude = std::fabs(value);
  if (value == 0 || (magnitude >= 1e-3 && magnitude < 1e6)) {
    const int integer_digits = value == 0 ? 1 : static_cast<int>(std::floor(std::log10(magnitude))) + 1;
    return fmt::format("{:.{}f}", value, std::max(0, digits - integer_digits));
  }
  return fmt::format("{:.{}e}", value, std::max(0, digits - 1));
}

std::string report_html(const std::vector<Section>& sections, const ReportOptions& options, double seconds) {
  std::string html = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  html += "<title>stratum: the lecture on sampling, reproduced</title>\n<style>" + std::string(style) + "</style>\n";
  html += "</head>\n<body>\n<h1>Sampling and Monte Carlo integration, reproduced</h1>\n";
  html += fmt::format(
      "<p class=\"meta\">Every figure and number below was computed by stratum on this machine in {:.0f} s "
      "({} run, seed {}{}). Regenerate with <code>stratum report{}</code>; the measurements are also in "
      "<a href=\"report.json\">report.json</a>.</p>\n",
      seconds, options.quick ? "quick" : "full", options.seed,
      options.extra_samplers.empty() ? "" : ", extra samplers " + escape(fmt::format("{}", fmt::join(options.extra_samplers, ", "))),
      options.quick ? " --quick" : "");
  html += "<nav><ol>\n";
  for (const auto& section : sections)
    html += fmt::format("<li><a href=\"#{}\">{} {}</a></li>\n", escape(section.id), escape(section.lecture),
                        escape(section.title));
  html += "</ol></nav>\n";
  for (const auto& section : sections) html += section_html(section);
  return html + "</body>\n</html>\n";
}

}  // namespace stratum::report
