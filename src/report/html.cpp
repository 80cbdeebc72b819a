/// The report page: plain HTML with inline CSS, figures by relative path,
/// no script and nothing fetched from a network, so it opens from disk.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cctype>
#include <cmath>
#include <string>
#include <thread>

#include "sections.hpp"
#include "stratum/registry/spec.hpp"

namespace stratum::report {

namespace {

std::string escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

constexpr const char* style = R"css(
:root { --fg: #222; --muted: #666; --bg: #fff; --line: #ccc; --head: #f4f4f4; --code: #f2f2f2; --link: #0645ad; }
@media (prefers-color-scheme: dark) {
  :root { --fg: #ddd; --muted: #aaa; --bg: #16181c; --line: #444; --head: #23262c; --code: #2a2d33; --link: #8ab4f8; }
  figure img { background: #fff; }
}
html { background: var(--bg); color: var(--fg); }
body { font-family: sans-serif; max-width: 1100px; margin: 2em auto; padding: 0 1em; line-height: 1.45; }
a { color: var(--link); }
h1 { margin-bottom: 0.2em; } h2 { border-bottom: 1px solid var(--line); padding-bottom: 0.2em; margin-top: 2em; }
.meta, figcaption, .time { color: var(--muted); font-size: 0.9em; }
.figures { display: flex; flex-wrap: wrap; gap: 1em; }
figure { margin: 0; max-width: 100%; } figure img { max-width: 100%; height: auto; border: 1px solid var(--line); }
.scroll { overflow-x: auto; max-width: 100%; }
table { border-collapse: collapse; margin: 1em 0; font-size: 0.92em; }
th, td { border: 1px solid var(--line); padding: 0.25em 0.6em; text-align: right; }
th { background: var(--head); } td:first-child, th:first-child { text-align: left; }
td.num { white-space: nowrap; }
caption { caption-side: top; text-align: left; font-weight: bold; padding-bottom: 0.3em; }
code { background: var(--code); padding: 0 0.25em; border-radius: 3px; font-size: 0.85em; overflow-wrap: anywhere; }
.try { border-left: 3px solid var(--line); padding-left: 0.6em; }
.formula { font-family: "DejaVu Serif", serif; }
dl.formulas { border-left: 3px solid var(--link); padding: 0.2em 0.8em; margin: 1em 0; background: var(--head); }
dl.formulas dt { color: var(--muted); font-size: 0.9em; } dl.formulas dd { margin: 0 0 0.4em 1em; overflow-wrap: anywhere; }
tr.topic th { text-align: left; } table.slides td, table.slides th { text-align: left; }
)css";

/// Escapes `text` and shows the parts between backticks as <code>.
std::string markup(const std::string& text) {
  std::string html;
  bool in_code = false;
  std::string part;
  const auto flush = [&] {
    html += in_code ? "<code>" + escape(part) + "</code>" : escape(part);
    part.clear();
  };
  for (const char c : text) {
    if (c == '`') {
      flush();
      in_code = !in_code;
    } else {
      part += c;
    }
  }
  if (in_code) part = "`" + part;  // an unmatched backtick stays a backtick
  in_code = false;
  flush();
  return html;
}

/// A formula as HTML: "x^(−1/2)" and "x^2" as superscripts, "U_i" and
/// "∫_(H²)" as subscripts (a group in parentheses, or a run of characters up
/// to a space or punctuation); the rest escaped.
std::string formula_html(const std::string& formula) {
  std::string html;
  for (std::size_t i = 0; i < formula.size(); ++i) {
    const char c = formula[i];
    if ((c != '^' && c != '_') || i + 1 == formula.size()) {
      html += escape(std::string(1, c));
      continue;
    }
    std::size_t begin = i + 1, end = begin;
    if (formula[begin] == '(') {
      int depth = 0;
      for (; end < formula.size(); ++end) {
        depth += formula[end] == '(' ? 1 : formula[end] == ')' ? -1 : 0;
        if (depth == 0) break;
      }
      ++begin;  // inside the parentheses
    } else {
      while (end < formula.size() && std::string_view(" ,;()[]/=|").find(formula[end]) == std::string_view::npos) ++end;
    }
    const std::string tag = c == '^' ? "sup" : "sub";
    html += "<" + tag + ">" + escape(formula.substr(begin, end - begin)) + "</" + tag + ">";
    i = formula[i + 1] == '(' ? end : end - 1;
  }
  return html;
}

/// A section's title up to its colon ("Importance sampling"), for links.
std::string short_title(const std::string& title) { return title.substr(0, title.find(':')); }

/// A cell that holds a measured number (it must not wrap: "5.35e-05").
bool numeric_cell(const std::string& cell) {
  if (cell.empty()) return false;
  const unsigned char c = static_cast<unsigned char>(cell[0]);
  return std::isdigit(c) || c == '-' || c == '+' || cell.rfind("−", 0) == 0 || cell.rfind("≥", 0) == 0 ||
         cell.rfind("≤", 0) == 0 || cell.rfind("∞", 0) == 0;
}

std::string table_html(const Table& table) {
  std::string html = table.id.empty() ? "<div class=\"scroll\"><table>\n"
                                      : "<div class=\"scroll\" id=\"table-" + escape(table.id) + "\"><table>\n";
  if (!table.caption.empty()) html += "<caption>" + markup(table.caption) + "</caption>\n";
  html += "<tr>";
  for (const auto& cell : table.header) html += "<th>" + markup(cell) + "</th>";
  html += "</tr>\n";
  for (const auto& row : table.rows) {
    html += "<tr>";
    for (const auto& cell : row) html += (numeric_cell(cell) ? "<td class=\"num\">" : "<td>") + markup(cell) + "</td>";
    html += "</tr>\n";
  }
  return html + "</table></div>\n";
}

/// The formulas of the section's slides, under its heading.
std::string formulas_html(const Section& section) {
  std::string items;
  for (const LectureSlide& slide : lecture_slides())
    if (slide.section == section.id && !slide.formula.empty())
      items +=
          fmt::format("<dt>{}</dt><dd class=\"formula\">{}</dd>\n", escape(slide.title), formula_html(slide.formula));
  return items.empty() ? "" : "<dl class=\"formulas\">\n" + items + "</dl>\n";
}

std::string section_html(const Section& section) {
  std::string html = fmt::format("<section id=\"{}\">\n<h2>{} {}</h2>\n", escape(section.id), escape(section.lecture),
                                 escape(section.title));
  html += formulas_html(section);
  for (const auto& paragraph : section.text) html += "<p>" + markup(paragraph) + "</p>\n";
  if (!section.figures.empty()) {
    html += "<div class=\"figures\">\n";
    for (const auto& figure : section.figures)
      html += fmt::format(
          "<figure id=\"{3}\"><a href=\"{0}\" title=\"full-size image\"><img src=\"{0}\" alt=\"{1}\"></a>"
          "<figcaption>{2}</figcaption></figure>\n",
          escape(figure.file), escape(figure.caption), markup(figure.caption), escape(figure_anchor(figure)));
    html += "</div>\n";
  }
  for (const auto& table : section.tables) html += table_html(table);
  if (!section.try_it.empty()) {
    html += "<p class=\"try\">Try it with other samplers: ";
    for (std::size_t i = 0; i < section.try_it.size(); ++i)
      html += (i ? "; " : "") + std::string("<code>") + escape(section.try_it[i]) + "</code>";
    html += "</p>\n";
  }
  html += fmt::format(
      "<p class=\"try\">This section alone, with an extra sampler: <code>stratum report --only {0} --sampler "
      "halton:owen</code>; in Python <code>stratum.report(\"out\", only=[\"{0}\"], "
      "samplers=[\"halton:owen\"])</code>.</p>\n",
      escape(section.id));
  html += fmt::format("<p class=\"time\">Computed in {}.</p>\n</section>\n", escape(format_seconds(section.seconds)));
  return html;
}

/// The lecture slide by slide: each slide's title and formula, and a link to
/// the figure or table that reproduces it.
std::string index_html(const std::vector<Section>& sections) {
  std::string html =
      "<nav><div class=\"scroll\"><table class=\"slides\">\n<caption>The lecture, slide by slide, and where each "
      "is reproduced</caption>\n<tr><th>slide</th><th>its formula</th><th>reproduced in</th></tr>\n";
  const std::vector<SlideLocation> located = locate_slides(sections);
  for (const auto& topic : lecture_topics()) {
    html += fmt::format("<tr class=\"topic\"><th colspan=\"3\">{} {}</th></tr>\n", escape(topic.lecture),
                        escape(topic.title));
    for (const SlideLocation& at : located) {
      if (at.slide->lecture != topic.lecture) continue;
      std::string where = "(not run: see <code>--only</code>)";
      if (at.section)
        where = fmt::format("{}<a href=\"#{}\">{}</a>",
                            at.found && !at.slide->anchor.empty()
                                ? fmt::format("<a href=\"#{}\">{}</a> in ", escape(at.slide->anchor),
                                              at.slide->anchor.rfind("table-", 0) == 0 ? "table" : "figure")
                                : "",
                            escape(at.section->id), escape(short_title(at.section->title)));
      html += fmt::format("<tr><td>{}</td><td class=\"formula\">{}</td><td>{}</td></tr>\n", escape(at.slide->title),
                          formula_html(at.slide->formula), where);
    }
  }
  return html + "</table></div></nav>\n";
}

}  // namespace

namespace {

/// The decimals that give `value` `digits` significant digits in fixed
/// notation, counted after rounding (0.9996 rounds to 1.00, not 1.000).
int fixed_decimals(double value, int digits) {
  const double magnitude = std::fabs(value);
  if (magnitude == 0) return std::max(0, digits - 1);
  const int integer_digits = static_cast<int>(std::floor(std::log10(magnitude))) + 1;
  const int decimals = std::max(0, digits - integer_digits);
  // Rounded up to the next power of ten, the value has one integer digit more.
  if (decimals > 0 && std::round(magnitude * std::pow(10.0, decimals)) >= std::pow(10.0, digits)) return decimals - 1;
  return decimals;
}

bool fixed_range(double value) {
  const double magnitude = std::fabs(value);
  return value == 0 || (magnitude >= 1e-3 && magnitude < 1e6);
}

}  // namespace

std::string format_number(double value, int digits) {
  if (!std::isfinite(value)) return std::isnan(value) ? "n/a" : (value > 0 ? "∞" : "−∞");
  if (fixed_range(value)) return fmt::format("{:.{}f}", value, fixed_decimals(value, digits));
  return fmt::format("{:.{}e}", value, std::max(0, digits - 1));
}

FormattedInterval format_alike(double estimate, double low, double high, int digits) {
  const bool fixed = std::isfinite(estimate) && std::isfinite(low) && std::isfinite(high) && fixed_range(estimate) &&
                     fixed_range(low) && fixed_range(high);
  if (fixed) {
    // The estimate's decimals, or more where a bound would keep fewer than
    // two significant digits with them.
    int decimals = fixed_decimals(estimate, digits);
    for (const double bound : {low, high})
      if (bound != 0) decimals = std::max(decimals, fixed_decimals(bound, 2));
    if (decimals <= digits + 3) {
      const auto fixed_text = [&](double v) { return fmt::format("{:.{}f}", v, decimals); };
      return {fixed_text(estimate), fixed_text(low), fixed_text(high)};
    }
  }
  return {format_number(estimate, digits), format_number(low, digits), format_number(high, digits)};
}

std::string report_html(const std::vector<Section>& sections, const ReportOptions& options, double seconds) {
  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      "<meta name=\"color-scheme\" content=\"light dark\">\n";
  html += "<title>stratum: the lecture on sampling, reproduced</title>\n<style>" + std::string(style) + "</style>\n";
  html += "</head>\n<body>\n<h1>Sampling and Monte Carlo integration, reproduced</h1>\n";
#ifndef STRATUM_VERSION_TEXT
#define STRATUM_VERSION_TEXT "unknown"
#endif
#if defined(__clang__)
  const std::string compiler = fmt::format("Clang {}.{}", __clang_major__, __clang_minor__);
#elif defined(__GNUC__)
  const std::string compiler = fmt::format("GCC {}.{}", __GNUC__, __GNUC_MINOR__);
#else
  const std::string compiler = "an unknown compiler";
#endif
  html += fmt::format(
      "<p class=\"meta\">Every figure and number below was computed by stratum {} (built with {}) on this machine "
      "({}, {} used) in {} ({} run, seed {}{}). Regenerate with <code>stratum report{}</code>; the "
      "measurements are also in <a href=\"report.json\">report.json</a>.</p>\n",
      STRATUM_VERSION_TEXT, escape(compiler), counted(std::max(1u, std::thread::hardware_concurrency()), "core"),
      counted(stratum::resolve_threads(options.threads), "thread"), escape(format_seconds(seconds)),
      options.quick ? "quick" : "full", options.seed,
      options.extra_samplers.empty()
          ? ""
          : ", extra samplers " + escape(fmt::format("{}", fmt::join(options.extra_samplers, ", "))),
      options.quick ? " --quick" : "");
  html += index_html(sections);
  for (const auto& section : sections) html += section_html(section);
  return html + "</body>\n</html>\n";
}

}  // namespace stratum::report
