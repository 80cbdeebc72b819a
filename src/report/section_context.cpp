#include "section_context.hpp"

#include <utility>

#include "stratum/render/render.hpp"

namespace stratum::report {

SectionContext::SectionContext(const ReportOptions& options, const SectionInfo& info, std::filesystem::path staging,
                               unsigned threads, std::vector<plot::PlotJob>& plots)
    : options_(options), info_(info), staging_(std::move(staging)), threads_(threads), plots_(plots) {}

std::vector<analysis::SamplerChoice> SectionContext::extra_samplers() const {
  std::vector<analysis::SamplerChoice> choices;
  for (const auto& text : options_.extra_samplers) choices.push_back(analysis::parse_sampler_choice(text));
  return choices;
}

Section SectionContext::start() const {
  Section section;
  section.id = info_.id;
  section.lecture = info_.lecture;
  section.title = info_.title;
  return section;
}

std::string SectionContext::figure_file(const std::string& name) const {
  return "figures/" + info_.id + "-" + name + ".png";
}

Figure SectionContext::plot(std::string_view script, nlohmann::json data, const std::string& name,
                            const std::string& caption) {
  Figure figure{figure_file(name), caption};
  plots_.push_back(plot::PlotJob{std::string(script), std::move(data), (staging_ / figure.file).string()});
  return figure;
}

Figure SectionContext::image(const render::Image& image, const std::string& name, const std::string& caption) {
  Figure figure{figure_file(name), caption};
  render::write_image(image, (staging_ / figure.file).string());
  return figure;
}

}  // namespace stratum::report
