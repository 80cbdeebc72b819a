/// `stratum spectrum`: the mean periodogram of point files or of a sampler's
/// realizations, its radial profile and anisotropy, the effective Nyquist
/// frequency and oscillation; text, JSON and a figure (image + radial plot).
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "sampler_options.hpp"
#include "stratum/io/output_file.hpp"
#include "stratum/plot.hpp"
#include "stratum/analysis/image_spectrum.hpp"
#include "stratum/analysis/spectrum.hpp"
#include "stratum/io/read_points.hpp"
#include "stratum/registry.hpp"
#ifdef STRATUM_HAS_RENDER
#include "stratum/render/compare.hpp"
#endif
#include "stratum/util/error.hpp"

namespace stratum::cli {
namespace {
namespace sa = stratum::analysis;

struct SpectrumOptions : SamplerOptions {
  std::vector<std::string> files;
  std::string png;
  std::optional<std::int64_t> n, max_frequency;
  std::int64_t realizations = 1, threads = 0;
  bool json = false;
  std::string image, reference;     ///< --image: the spectrum of an image (or of image − reference)
  std::vector<std::string> frames;  ///< --frames: the temporal spectrum of an animation's frames
};

std::vector<PointSet> load_realizations(const SpectrumOptions& o) {
  if (o.files.empty() == o.sampler.empty())
    throw invalid_argument("input", o.files.empty() ? "(none)" : o.files.front() + " and --sampler " + o.sampler,
                           "give point FILEs (one per realization) or --sampler S -n N");
  std::vector<PointSet> sets;
  if (!o.files.empty()) {
    if (o.n) throw invalid_argument("-n", o.files.front(), "applies only to --sampler; a FILE has its own size");
    if (!o.params.empty() || !o.randomize.empty())
      throw invalid_argument(o.params.empty() ? "randomize" : "param",
                             o.params.empty() ? o.randomize : o.params.front(),
                             "applies only to --sampler; a FILE is read as it is");
    if (o.realizations != 1)
      throw invalid_argument("realizations", std::to_string(o.realizations),
                             "applies only to --sampler; give one FILE per realization");
    for (const auto& file : o.files) {
      sets.push_back(io::read_points_strict(file));
      io::check_unit_cube(sets.back(), file);  // naming the line at fault
    }
    return sets;
  }
  require(o.n.has_value(), "n", "(missing)", "--sampler needs -n N");
  require(*o.n >= 2, "n", *o.n, "must be an integer >= 2");
  require(o.realizations >= 1 && o.realizations <= 100000, "realizations", o.realizations, "must be in [1, 100000]");
  const SamplerSpec spec = o.spec();
  for (std::int64_t r = 0; r < o.realizations; ++r) {
    SamplerRequest request = o.request(spec);
    request.n = static_cast<std::uint64_t>(*o.n);
    request.d = 2;
    request.seed = o.seed + static_cast<std::uint64_t>(r);  // realization r uses seed + r
    request.threads = static_cast<unsigned>(o.threads);
    sets.push_back(generate_points(spec.name, request));
  }
  return sets;
}

#ifdef STRATUM_HAS_RENDER
/// The luminance of `image`, or of image − reference (sizes checked).
std::vector<double> luminance_values(const render::Image& image, const std::optional<render::Image>& reference) {
  if (reference) return render::luminance_error(image, *reference);
  render::Image black = image;
  std::fill(black.rgb.begin(), black.rgb.end(), 0.0);
  return render::luminance_error(image, black);
}
#endif

/// `spectrum --image`: where an image's variation (a render's error) goes
/// in frequency (analysis/image_spectrum.hpp), of its luminance, or of the
/// luminance of image − reference.
void run_image_spectrum(const SpectrumOptions& o) {
#ifdef STRATUM_HAS_RENDER
  if (!o.files.empty() || !o.sampler.empty())
    throw invalid_argument("--image", o.image, "measures an image alone: give no point FILEs and no --sampler");
  if (!o.png.empty())
    throw invalid_argument("--output", o.png, "draws point-set spectra; for --image use --json (radial power)");
  const render::Image image = render::read_image(o.image);
  std::optional<render::Image> reference;
  if (!o.reference.empty()) reference = render::read_image(o.reference);
  const std::vector<double> values = luminance_values(image, reference);
  const sa::ImageSpectrum s = sa::image_spectrum(values, image.width, image.height);
  nlohmann::json power = nlohmann::json::array();
  for (double p : s.radial_power) power.push_back(std::isfinite(p) ? nlohmann::json(p) : nullptr);
  const nlohmann::json data = {
      {"source", o.image},
      {"reference", o.reference.empty() ? nlohmann::json(nullptr) : nlohmann::json(o.reference)},
      {"width", s.width},
      {"height", s.height},
      {"variance", s.variance},
      {"low_frequency_power", s.low_frequency_power},
      {"radial", {{"frequency", s.radial_frequency}, {"power", power}}}};
  if (o.json) {
    fmt::print("{}\n", data.dump(2));
    return;
  }
  fmt::print("# spectrum of the luminance of {}{} ({}x{}), normalized: white noise = 1\n", o.image,
             o.reference.empty() ? "" : " - " + o.reference, s.width, s.height);
  fmt::print("low_frequency_power {:.6g}   (mean below a quarter of Nyquist; < 1: blue noise)\n",
             s.low_frequency_power);
  fmt::print("variance            {:.6g}\n", s.variance);
  fmt::print("# {:>10} {:>12}\n", "frequency", "power");
  for (std::size_t r = 0; r < s.radial_power.size(); ++r)
    fmt::print("  {:>10.5f} {:>12.6g}\n", s.radial_frequency[r], s.radial_power[r]);
#else
  throw invalid_argument("--image", o.image, "needs the renderer's image reader (a build with STRATUM_BUILD_RENDER)");
#endif
}

/// `spectrum --frames`: where each pixel's variation (a render's error)
/// goes in time over an animation's frames (analysis::temporal_spectrum), of
/// the luminance. No reference: each pixel's mean over the frames is removed,
/// so the error's spectrum equals the luminance's.
void run_temporal_spectrum(const SpectrumOptions& o) {
#ifdef STRATUM_HAS_RENDER
  if (!o.files.empty() || !o.sampler.empty() || !o.image.empty())
    throw invalid_argument("--frames", o.frames.front(),
                           "measures frames alone: give no point FILEs, no --sampler and no --image");
  if (!o.png.empty()) throw invalid_argument("--output", o.png, "draws point-set spectra; for --frames use --json");
  if (o.frames.size() < 9)
    throw invalid_argument("--frames", std::to_string(o.frames.size()) + " files",
                           "needs at least 9 frames (the lowest frequency 1/F must lie below 1/8 cycle per frame)");
  if (!o.reference.empty())
    throw invalid_argument("--reference", o.reference,
                           "does not apply to --frames: each pixel's mean over the frames is removed, so a "
                           "reference would cancel");
  std::vector<std::vector<double>> values;
  int width = 0, height = 0;
  for (const auto& file : o.frames) {
    const render::Image frame = render::read_image(file);
    if (values.empty()) {
      width = frame.width;
      height = frame.height;
    } else if (frame.width != width || frame.height != height) {
      throw invalid_argument("--frames", file,
                             fmt::format("is {}x{}; every frame must have the size of the first, {}x{}", frame.width,
                                         frame.height, width, height));
    }
    values.push_back(luminance_values(frame, std::nullopt));
  }
  const sa::TemporalSpectrum s = sa::temporal_spectrum(values, width, height);
  const nlohmann::json data = {{"frames", o.frames},
                               {"width", s.width},
                               {"height", s.height},
                               {"variance", s.variance},
                               {"low_frequency_power", s.low_frequency_power},
                               {"lag1_correlation", s.lag1_correlation},
                               {"temporal", {{"frequency", s.frequency}, {"power", s.power}}}};
  if (o.json) {
    fmt::print("{}\n", data.dump(2));
    return;
  }
  fmt::print("# temporal spectrum of each pixel's luminance over {} frames ({}x{}), white in time = 1\n", s.frames,
             s.width, s.height);
  fmt::print("low_frequency_power {:.6g}   (mean below 1/8 cycle per frame; < 1: blue in time)\n",
             s.low_frequency_power);
  fmt::print("lag1_correlation    {:.6g}   (consecutive frames; about -1/F when independent)\n", s.lag1_correlation);
  fmt::print("variance            {:.6g}\n", s.variance);
  fmt::print("# {:>10} {:>12}\n", "cycles/frame", "power");
  for (std::size_t k = 0; k < s.power.size(); ++k) fmt::print("  {:>12.5f} {:>12.6g}\n", s.frequency[k], s.power[k]);
#else
  throw invalid_argument("--frames", o.frames.front(),
                         "needs the renderer's image reader (a build with STRATUM_BUILD_RENDER)");
#endif
}

void run_spectrum(const SpectrumOptions& o) {
  if (!o.frames.empty()) return run_temporal_spectrum(o);
  if (!o.image.empty()) return run_image_spectrum(o);
  if (!o.reference.empty()) throw invalid_argument("--reference", o.reference, "applies only to --image");
  const auto figure = plot::prepare_plot("output", o.png);  // checked before the work
  if (o.max_frequency)
    require(*o.max_frequency >= 1 && *o.max_frequency <= 1 << 24, "max-frequency", *o.max_frequency,
            "must be an integer in [1, 2^24] (and (2K+1)^d at most 2^25 values)");
  const std::vector<PointSet> sets = load_realizations(o);
  std::vector<sa::PointView> views;
  for (const auto& s : sets) views.push_back({s.data.get(), s.n, s.d});
  const std::size_t n = views.front().n;
  // Default K: 2.5 √N (the first peak of blue noise lies near √N), at least 16.
  const int k = static_cast<int>(o.max_frequency.value_or(std::min<std::int64_t>(
      1024, std::max<std::int64_t>(16, static_cast<std::int64_t>(std::ceil(2.5 * std::sqrt(n)))))));
  const sa::Periodogram p = sa::mean_periodogram(views, k, static_cast<unsigned>(o.threads));
  const sa::RadialPower radial = sa::radial_average(p);
  const sa::BlueNoiseFigures figures = sa::blue_noise_figures(radial);

  nlohmann::json data = {{"source", o.files.empty() ? "sampler " + o.sampler : o.files.front()},
                         {"n", n},
                         {"d", p.d},
                         {"realizations", p.realizations},
                         {"max_frequency", k},
                         {"frequency_scale", sa::radial_frequency_scale(n)},
                         {"radial",
                          {{"frequency", radial.frequency},
                           {"radius", radial.radius},
                           {"power", radial.power},
                           {"anisotropy_db", radial.anisotropy_db}}},
                         {"effective_nyquist", figures.effective_nyquist},
                         {"nyquist_is_lower_bound", figures.nyquist_is_lower_bound},
                         {"oscillation", figures.oscillation},
                         {"oscillation_window", {figures.oscillation_from, figures.oscillation_to}},
                         {"oscillation_window_is_cut", figures.window_is_cut},
                         {"power", p.power}};
  if (figure) plot::write_plot("spectrum", data, *figure);
  if (o.json) {
    fmt::print("{}\n", data.dump(2));
    return;
  }
  fmt::print("# spectrum of {} ({} points, d = {}, {} realization{}), frequencies |k| <= {}\n",
             data["source"].get<std::string>(), n, p.d, p.realizations, p.realizations == 1 ? "" : "s", k);
  fmt::print("# frequencies are given in units of sqrt(N) = {:.6g}\n", sa::radial_frequency_scale(n));
  fmt::print("effective_nyquist {:.6g}{}\n", figures.effective_nyquist,
             figures.nyquist_is_lower_bound ? " (lower bound: raise --max-frequency)" : "");
  fmt::print("oscillation       {:.6g}{}\n", figures.oscillation,
             figures.window_is_cut ? " (window cut at --max-frequency)" : "");
  fmt::print("# {:>10} {:>8} {:>12} {:>14}\n", "frequency", "radius", "power", "anisotropy_db");
  for (std::size_t r = 0; r < radial.power.size(); ++r)
    fmt::print("  {:>10.5f} {:>8} {:>12.6g} {:>14.4g}\n", radial.frequency[r], radial.radius[r], radial.power[r],
               radial.anisotropy_db[r]);
}
}  // namespace

void add_spectrum_command(CLI::App& app) {
  auto o = std::make_shared<SpectrumOptions>();
  auto* command = app.add_subcommand(
      "spectrum",
      "Fourier spectrum of a 2D (or 1D) point set: radial power, anisotropy, effective Nyquist, oscillation");
  command->add_option("files", o->files, "point files, one per realization (.txt, .csv, .npy); or use --sampler");
  add_sampler_options(*command, *o, "use this sampler's 2D points (realization r: seed + r)",
                      "seed of the first realization");
  command->add_option("-n", o->n, "number of points (with --sampler)");
  command->add_option("--realizations", o->realizations, "realizations to average (with --sampler)")
      ->capture_default_str();
  command->add_option("-k,--max-frequency", o->max_frequency,
                      "largest integer frequency K per axis (default: 2.5 sqrt(N), at least 16, at most 1024)");
  add_threads_option(*command, o->threads, "threads (results do not depend on it)");
  command->add_option("-o,--output", o->png, "write a PNG: spectrum image and radial plot");
  command->add_flag("--json", o->json, "print JSON (with the full periodogram `power`, row-major, ky then kx)");
  command->add_option("--image", o->image,
                      "instead: the power spectrum of an image's luminance (.exr, .png, ...), e.g. a render's error");
  command->add_option("--frames", o->frames,
                      "instead: the temporal spectrum of frames F0 F1 ... (at least 9 images of one size): where "
                      "each pixel's luminance (its error) goes in time");
  command->add_option("--reference", o->reference, "with --image: the spectrum of image - reference");
  command->callback([o] { run_spectrum(*o); });
}

}  // namespace stratum::cli
