/// §8 in time: the slide's "nearby samples in space should differ greatly in
/// time" at the scale of frames. Frame K of a progressive or blue-noise pixel
/// sampler takes each pixel's next block of its sequence (Heitz & Belcour
/// 2019 permute pixel seeds between frames for the same end), so consecutive
/// frames' errors cancel: measured by the temporal spectrum of each pixel's
/// error (Wolfe et al. 2022) and by frames averaged.
#include "space_time_frames.hpp"

#include <fmt/core.h>

#include <algorithm>

#include "render_support.hpp"
#include "stratum/analysis/image_spectrum.hpp"
#include "stratum/render/render.hpp"

namespace stratum::report {

namespace {

struct FrameRun {
  std::string sampler;
  analysis::TemporalSpectrum spectrum;
  double averaged_mse = 0, four_spp_mse = 0, independent_mse = 0;
  std::vector<std::vector<double>> errors;  ///< per frame: the luminance error per pixel
};

double mean_square(const std::vector<double>& e) {
  double sum = 0;
  for (const double v : e) sum += v * v;
  return sum / double(e.size());
}

}  // namespace

void frames_error(SectionContext& context, Section& section) {
  const int side = context.quick() ? 32 : 64;
  const int frames = context.quick() ? 16 : 32;
  render::Scene scene = render::penumbra_scene();
  scene.camera.width = scene.camera.height = side;
  render::RenderSettings settings;
  settings.passes = 1;
  settings.threads = context.threads();
  settings.sampler.sampler = "sobol";
  settings.sampler.spp = context.quick() ? 256 : 1024;
  settings.sampler.seed = context.seed() + 7919;  // the reference's seed differs from every frame's
  const render::Image reference = render::render(scene, settings);
  const auto error_of = [&](const std::string& sampler, std::uint32_t spp, std::uint32_t frame, std::uint64_t seed) {
    settings.sampler.sampler = sampler;
    settings.sampler.spp = spp;
    settings.sampler.frame = frame;
    settings.sampler.seed = seed;
    return render::luminance_error(render::render(scene, settings), reference);
  };

  std::vector<FrameRun> runs;
  for (const char* sampler : {"random", "sobol", "zsobol", "sobol-bn", "pmj02-bn"}) {
    FrameRun run{sampler, {}, 0, 0, 0, {}};
    for (int k = 0; k < frames; ++k) run.errors.push_back(error_of(sampler, 1, std::uint32_t(k), context.seed()));
    run.spectrum = analysis::temporal_spectrum(run.errors, side, side);
    // Frames 0–3 averaged; one frame at 4 spp; frame 0 of 4 other seeds averaged.
    std::vector<double> averaged(run.errors[0].size(), 0.0), independent(averaged.size(), 0.0);
    for (int k = 0; k < 4; ++k) {
      const std::vector<double> fresh = error_of(sampler, 1, 0, context.seed() + 1 + std::uint64_t(k));
      for (std::size_t p = 0; p < averaged.size(); ++p)
        averaged[p] += run.errors[k][p] / 4, independent[p] += fresh[p] / 4;
    }
    run.averaged_mse = mean_square(averaged);
    run.independent_mse = mean_square(independent);
    run.four_spp_mse = mean_square(error_of(sampler, 4, 0, context.seed()));
    runs.push_back(std::move(run));
  }

  Table table{fmt::format("A pixel's error across {} frames at 1 sample per pixel ({}×{} pixels of the floor in soft "
                          "shadow; luminance error; frame K continues each pixel's sequence)",
                          frames, side, side),
              {"sampler", "consecutive frames: error correlation", "temporal low-frequency power (white = 1)",
               "MSE, frames 0–3 averaged", "MSE, one frame at 4 spp", "MSE, 4 independent frames averaged"},
              {}};
  nlohmann::json series = nlohmann::json::array(), panels = nlohmann::json::array();
  const int row = side / 2;  // a row across the penumbras
  for (const FrameRun& run : runs) {
    const auto& s = run.spectrum;
    table.rows.push_back({run.sampler, format_number(s.lag1_correlation), format_number(s.low_frequency_power),
                          format_number(run.averaged_mse), format_number(run.four_spp_mse),
                          format_number(run.independent_mse)});
    section.numbers["frames_error"]["rows"][run.sampler] = {{"lag1_correlation", s.lag1_correlation},
                                                            {"low_frequency_power", s.low_frequency_power},
                                                            {"power", s.power},
                                                            {"averaged_4_frames_mse", run.averaged_mse},
                                                            {"one_frame_4_spp_mse", run.four_spp_mse},
                                                            {"independent_4_frames_mse", run.independent_mse}};
    series.push_back({{"label", run.sampler}, {"x", s.frequency}, {"y", s.power}});
    // The space-time slice: row `row`'s error (x across, frame down), grey is zero.
    render::Image slice;
    slice.width = side;
    slice.height = frames;
    slice.rgb.resize(std::size_t(side) * std::size_t(frames) * 3);
    for (int k = 0; k < frames; ++k)
      for (int x = 0; x < side; ++x)
        for (int c = 0; c < 3; ++c)
          slice.rgb[(std::size_t(k) * side + x) * 3 + c] = 0.5 + run.errors[k][std::size_t(row) * side + x];
    panels.push_back(image_panel(slice, run.sampler));
  }
  section.numbers["frames_error"]["frames"] = frames;
  section.numbers["frames_error"]["width"] = side;
  section.numbers["frames_error"]["reference_spp"] = context.quick() ? 256 : 1024;
  section.tables.push_back(std::move(table));
  section.figures.push_back(image_figure(
      context, panels, "frames-slice",
      fmt::format("Space against time: the error of one row of pixels (across) in frames 0 to {} (down), 1 sample per "
                  "pixel, grey is zero. Random's error is noise in both directions; the continued samplers' error "
                  "alternates in sign from frame to frame and between neighbouring pixels",
                  frames - 1),
      int(runs.size())));
  series.push_back({{"label", "white in time"},
                    {"x", {runs.front().spectrum.frequency.front(), runs.front().spectrum.frequency.back()}},
                    {"y", {1.0, 1.0}},
                    {"reference", true}});
  section.figures.push_back(context.plot(
      "report_lines",
      {{"panels",
        {{{"title", "Temporal power spectrum of a pixel's error"},
          {"xlabel", "frequency (cycles per frame)"},
          {"ylabel", "power (white in time = 1)"},
          {"xlog", false},
          {"ylog", true},
          {"series", series}}}}},
      "frames-spectra",
      "Each pixel's error over the frames, transformed over time and pooled over the pixels: independent frames are "
      "flat at 1; a sequence continued from frame to frame has little power at low frequencies, so frames averaged "
      "(by the eye, or by temporal accumulation) cancel"));

  const auto at = [&](const std::string& name) -> const FrameRun& {
    return *std::find_if(runs.begin(), runs.end(), [&](const FrameRun& r) { return r.sampler == name; });
  };
  const FrameRun &random = at("random"), &bn = at("sobol-bn"), &z = at("zsobol");
  section.text.push_back(fmt::format(
      "Across the frames of an animation (stratum render --frame K) the rule runs in time. A progressive or "
      "blue-noise sampler's frame K takes each pixel's next block of its sequence, so frames 0…K−1 together are one "
      "stratified set of K·spp samples (tested), and a pixel's error in consecutive frames cancels instead of "
      "repeating: over {} frames at 1 sample per pixel, the correlation of consecutive frames' errors is {} for "
      "random, {} for sobol-bn and {} for ZSobol, and the power of a pixel's error below 1/8 cycle per frame is {}, "
      "{} and {} (white in time = 1). Averaged, frames 0–3 of sobol-bn have MSE {}, against {} for one frame at 4 "
      "samples per pixel and {} for 4 independent frames; random's {}, {} and {}.",
      frames, format_number(random.spectrum.lag1_correlation), format_number(bn.spectrum.lag1_correlation),
      format_number(z.spectrum.lag1_correlation), format_number(random.spectrum.low_frequency_power),
      format_number(bn.spectrum.low_frequency_power), format_number(z.spectrum.low_frequency_power),
      format_number(bn.averaged_mse), format_number(bn.four_spp_mse), format_number(bn.independent_mse),
      format_number(random.averaged_mse), format_number(random.four_spp_mse), format_number(random.independent_mse)));
  section.text.push_back(
      "Cook's pattern and the magic square are the special case of this rule inside one pixel and one frame: they "
      "give a pixel's spatial strata time slots far apart, so that neighbours in space differ in time. ZSobol and the "
      "ranked samplers apply the same \"nearby in space, far apart in the sequence\" at the two larger scales: "
      "between neighbouring pixels (their blocks together form one stratified set, so their errors cancel on the "
      "screen) and between consecutive frames (the next block of the same set, so the errors cancel in time). "
      "Time within the shutter stays a dimension of each sample, which the assignments above stratify.");
}

}  // namespace stratum::report
