/// Running the report: validate every option, run the sections into a
/// staging folder, draw the queued figures, then move the page into place.
#include "stratum/report/report.hpp"

#include <fmt/core.h>
#include <stdlib.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <thread>

#include "section_context.hpp"
#include "sections.hpp"
#include "stratum/io/output_file.hpp"
#include "stratum/registry.hpp"
#include "stratum/registry/spec.hpp"
#include "stratum/util/error.hpp"

namespace stratum::report {

namespace fs = std::filesystem;

namespace {

std::string section_ids() {
  std::string ids;
  for (const auto& section : report_sections()) ids += (ids.empty() ? "" : ", ") + section.id;
  return ids;
}

void validate_extra_sampler(const std::string& text) {
  const auto choice = analysis::parse_sampler_choice(text);
  const SamplerInfo* info = nullptr;
  for (const auto& sampler : samplers())
    if (sampler.name == choice.name) info = &sampler;
  if (!info) {
    std::string names;
    for (const auto& sampler : samplers()) names += (names.empty() ? "" : ", ") + sampler.name;
    throw invalid_argument("sampler", text, "a registry sampler (" + names + "), optionally name:randomizer");
  }
  if (info->min_dim > 2 || info->max_dim < 2) throw invalid_argument("sampler", text, "a sampler that makes 2D points");
  if (!choice.randomize.empty() &&
      std::find(info->randomizers.begin(), info->randomizers.end(), choice.randomize) == info->randomizers.end()) {
    std::string allowed;
    for (const auto& r : info->randomizers) allowed += (allowed.empty() ? "" : ", ") + r;
    throw invalid_argument("sampler", text, "a randomizer of " + info->name + " (" + allowed + ")");
  }
}

/// A folder removed with everything in it when it goes out of scope (unless released).
struct StagingFolder {
  fs::path path;
  ~StagingFolder() {
    std::error_code ignored;
    if (!path.empty()) fs::remove_all(path, ignored);
  }
};

}  // namespace

void validate_report_options(const ReportOptions& options) {
  if (options.directory.empty()) throw invalid_argument("directory", "\"\"", "a folder path");
  if (options.threads > 1024)
    throw invalid_argument("threads", std::to_string(options.threads), "0 (every core) to 1024");
  for (const auto& text : options.extra_samplers) validate_extra_sampler(text);
  for (const auto& id : options.only) {
    const auto& all = report_sections();
    if (std::none_of(all.begin(), all.end(), [&](const SectionInfo& s) { return s.id == id; }))
      throw invalid_argument("only", id, "a section id (" + section_ids() + ")");
  }
  std::error_code error;
  const fs::path directory(options.directory);
  if (fs::exists(directory, error) && !fs::is_directory(directory, error))
    throw invalid_argument("directory", options.directory, "a folder (this is a file)");
}

ReportResult write_report(const ReportOptions& options, const std::function<void(const std::string&)>& progress) {
  validate_report_options(options);
  const auto started = std::chrono::steady_clock::now();
  const fs::path directory(options.directory);
  std::error_code error;
  fs::create_directories(directory, error);
  if (error)
    throw invalid_argument("directory", options.directory, "a folder this user can create (" + error.message() + ")");
  // The page and its numbers checked and staged before any section runs
  // (io::OutputFile: links written through, permissions kept).
  io::OutputGroup pages;
  io::OutputFile* report_json = pages.add("directory", (directory / "report.json").string());
  io::OutputFile* index_html = pages.add("directory", (directory / "index.html").string());
  pages.prepare();
  StagingFolder staging{io::make_staging_folder(directory, "report")};  // a kill -9 leftover: removed by the next run
  fs::create_directory(staging.path / "figures");

  const unsigned threads = stratum::resolve_threads(options.threads);  // the one thread rule (spec.hpp)
  std::vector<plot::PlotJob> plots;
  ReportResult result;
  for (const auto& info : report_sections()) {
    if (!options.only.empty() && std::find(options.only.begin(), options.only.end(), info.id) == options.only.end())
      continue;
    if (progress) progress(fmt::format("{} {}: {} ...", info.lecture, info.id, info.title));
    const auto section_start = std::chrono::steady_clock::now();
    SectionContext context(options, info, staging.path, threads, plots);
    Section section = info.build(context);
    section.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - section_start).count();
    if (progress) progress(fmt::format("{} {}: done in {:.1f} s", info.lecture, info.id, section.seconds));
    result.sections.push_back(std::move(section));
  }
  if (progress) progress(fmt::format("drawing {} figures ...", plots.size()));
  plot::write_plots(plots, threads);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  nlohmann::json numbers = {{"quick", options.quick},
                            {"seed", options.seed},
                            {"threads", threads},
                            {"extra_samplers", options.extra_samplers},
                            {"seconds", result.seconds}};
  for (const auto& section : result.sections)
    numbers["sections"][section.id] = {{"lecture", section.lecture},
                                       {"title", section.title},
                                       {"seconds", section.seconds},
                                       {"numbers", section.numbers}};
  // The lecture's slides, each with where this run reproduced it.
  numbers["slides"] = nlohmann::json::array();
  for (const SlideLocation& at : locate_slides(result.sections))
    numbers["slides"].push_back({{"lecture", at.slide->lecture},
                                 {"title", at.slide->title},
                                 {"formula", at.slide->formula},
                                 {"section", at.slide->section},
                                 {"anchor", at.slide->anchor},
                                 {"run", at.section != nullptr},
                                 {"shown", at.found}});
  const std::string json_text = numbers.dump(1);
  const std::string html_text = report_html(result.sections, options, result.seconds);
  report_json->write([&](std::ostream& out) { out << json_text; });
  index_html->write([&](std::ostream& out) { out << html_text; });

  // Into place: figures first, the page last, so index.html only ever
  // appears beside a complete set of figures.
  fs::remove_all(directory / "figures");
  fs::rename(staging.path / "figures", directory / "figures");
  pages.commit();
  result.index = (directory / "index.html").string();
  return result;
}

}  // namespace stratum::report
