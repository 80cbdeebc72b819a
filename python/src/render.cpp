/// Rendering from Python (LECTURE.md §1–3, 8, 9): render(), compare() and
/// comparisons(), over the same C++ API as `stratum render` and `stratum
/// compare` (only with the renderer built).
#ifdef STRATUM_HAS_RENDER
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <nlohmann/json.hpp>

#include "bindings.hpp"
#include "interruptible.hpp"
#include "stratum/util/interrupt.hpp"
#include "stratum/io/json.hpp"
#include "stratum/render/compare.hpp"
#include "stratum/render/compare_repeated.hpp"
#include "stratum/util/error.hpp"

namespace py = pybind11;

namespace stratum::python {

namespace {

/// (height, width, 3) float64, copied from an image's row-major RGB values.
py::array_t<double> to_array(const std::vector<double>& values, int width, int height) {
  py::array_t<double> out({py::ssize_t(height), py::ssize_t(width), py::ssize_t(3)});
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

void check_size(const char* name, int value) {
  require(value >= 0 && value <= 16384, name, value, "must be in [1, 16384] (or None: the scene's)");
}

py::tuple render_image(const std::string& scene_path, int width, int height, const render::RenderSettings& settings,
                       std::uint32_t reference_spp, const std::string& cache) {
  check_size("width", width);
  check_size("height", height);
  render::validate_settings(settings);
  render::Scene scene = scene_path.empty() ? render::cornell_box() : render::load_scene(scene_path);
  if (width > 0) scene.camera.width = width;
  if (height > 0) scene.camera.height = height;
  render::Image image;
  bool cached = false;
  {
    InterruptibleRelease release;  // Ctrl-C: KeyboardInterrupt
    image = reference_spp > 0 ? render::reference_image(scene, render::scene_fingerprint(scene), settings,
                                                        reference_spp, cache, &cached)
                              : render::render(scene, settings, {}, &interrupt_flag());
  }
  if (image.stopped) throw interrupted();  // Ctrl-C: KeyboardInterrupt, no partial image
  py::object variance = py::none();
  if (image.variance.size() == image.rgb.size()) variance = to_array(image.variance, image.width, image.height);
  return py::make_tuple(to_array(image.rgb, image.width, image.height), variance, image.samples, image.seconds, cached);
}

py::list compare_rows(const std::string& scene_path, const std::string& builtin, const std::string& configs_json,
                      render::CompareOptions options, int width, int height, unsigned threads, std::uint64_t seed,
                      unsigned repeats, double confidence) {
  std::vector<render::CompareConfig> configs;
  if (configs_json.empty()) {
    configs = render::builtin_comparison(builtin, threads, seed);
  } else {
    configs = render::parse_configs(io::parse_json(configs_json, "configs", "(the configs given)"), threads, seed);
  }
  const bool keep_motion = configs_json.empty() && builtin == "time-pattern";
  const auto prepared = render::comparison_scene(scene_path, keep_motion, width, height);
  render::RepeatedCompare repeated;
  {
    InterruptibleRelease release;  // Ctrl-C: KeyboardInterrupt
    repeated = render::compare_repeated(prepared.scene, prepared.key, configs, options, repeats, confidence);
  }
  const auto interval = [](const analysis::RatioInterval& i) { return py::make_tuple(i.low, i.high); };
  py::list out;
  for (std::size_t c = 0; c < repeated.summary.size(); ++c) {
    const render::CompareRow& r = repeated.summary[c];
    py::dict row(py::arg("label") = r.label, py::arg("spp") = r.samples, py::arg("passes") = r.passes,
                 py::arg("mse") = r.mse, py::arg("relative_mse") = r.relative_mse, py::arg("seconds") = r.seconds,
                 py::arg("efficiency") = r.efficiency, py::arg("mse_ratio") = r.mse_ratio,
                 py::arg("efficiency_ratio") = r.efficiency_ratio);
    if (!r.variance_path.empty()) row["variance"] = r.variance_path;
    row["scene_note"] = prepared.note;                   // what the comparison's scene leaves out ("" when nothing)
    row["low_frequency_power"] = r.low_frequency_power;  // NaN where the error has no spectrum
    row["error_spectrum"] =
        py::dict(py::arg("frequency") = r.error_radial_frequency, py::arg("power") = r.error_radial_power);
    if (repeats > 1) {  // the statistics over the repeats, as `stratum compare --repeats --json`
      const render::RepeatedStatistics& st = repeated.statistics[c];
      row["mse_per_seed"] = repeated.mse[c];
      row["seconds_per_seed"] = repeated.seconds[c];
      row["mse_standard_error"] = st.mse.standard_error;
      row["mse_ratio_interval"] = interval(st.mse_ratio);
      row["time_ratio"] = st.time_ratio.estimate;
      row["time_ratio_interval"] = interval(st.time_ratio);
      row["efficiency_ratio_interval"] = interval(st.efficiency_ratio);
      row["time_resolved"] = st.time_resolved;
    }
    out.append(row);
  }
  return out;
}

}  // namespace

void bind_render(py::module_& m) {
  m.def(
      "render",
      [](const std::string& scene, int width, int height, std::uint32_t spp, const std::string& integrator,
         std::uint32_t light_samples, const std::string& light_strategy, const std::string& hemisphere,
         std::uint32_t max_depth, const std::string& sampler, const std::string& randomize,
         const std::string& time_pattern, std::uint64_t seed, unsigned threads, std::uint32_t passes,
         bool pixel_centers, std::uint32_t reference_spp, const std::string& cache, std::uint32_t frame) {
        render::RenderSettings s;
        s.integrator = integrator;
        s.light_samples = light_samples;
        s.light_strategy = light_strategy;
        s.hemisphere = hemisphere;
        s.max_depth = max_depth;
        s.sampler = render::PixelSamplerSettings{sampler, randomize, seed, spp, time_pattern};
        render::set_pixel_sampler(s.sampler, "sampler", sampler, {}, randomize);
        s.sampler.frame = frame;
        s.threads = threads;
        s.passes = passes;
        s.pixel_centers = pixel_centers;
        return render_image(scene, width, height, s, reference_spp, cache);
      },
      py::arg("scene"), py::arg("width"), py::arg("height"), py::arg("spp"), py::arg("integrator"),
      py::arg("light_samples"), py::arg("light_strategy"), py::arg("hemisphere"), py::arg("max_depth"),
      py::arg("sampler"), py::arg("randomize"), py::arg("time_pattern"), py::arg("seed"), py::arg("threads"),
      py::arg("passes"), py::arg("pixel_centers"), py::arg("reference_spp"), py::arg("cache"), py::arg("frame"));
  m.def(
      "compare",
      [](const std::string& scene, const std::string& builtin, const std::string& configs, std::uint32_t reference_spp,
         const std::string& cache, double equal_time, const std::string& variance_dir, int width, int height,
         unsigned threads, std::uint64_t seed, unsigned repeats, double confidence) {
        render::CompareOptions options;
        options.reference_spp = reference_spp;
        options.cache_dir = cache;
        options.equal_time = equal_time;
        options.variance_dir = variance_dir;
        return compare_rows(scene, builtin, configs, options, width, height, threads, seed, repeats, confidence);
      },
      py::arg("scene"), py::arg("builtin"), py::arg("configs"), py::arg("reference_spp"), py::arg("cache"),
      py::arg("equal_time"), py::arg("variance_dir"), py::arg("width"), py::arg("height"), py::arg("threads"),
      py::arg("seed"), py::arg("repeats"), py::arg("confidence"));
  m.def("comparisons", [] {
    py::list list;
    for (const auto& [name, description] : render::builtin_comparisons())
      list.append(py::dict(py::arg("name") = name, py::arg("description") = description));
    return list;
  });
}

}  // namespace stratum::python
#endif
