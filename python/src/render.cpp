/// Rendering from Python (LECTURE.md §1–3, 8, 9): render(), compare() and
/// comparisons(), over the same C++ API as `stratum render` and `stratum
/// compare` (only with the renderer built).
#ifdef STRATUM_HAS_RENDER
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <nlohmann/json.hpp>

#include "bindings.hpp"
#include "interruptible.hpp"
#include "keywords.hpp"
#include "stratum/render/render_job.hpp"
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

/// render(**kwargs): the keywords of stratum.render() (python/stratum/render.py),
/// read into a RenderJob that the library checks, as the CLI's.
py::tuple render_job(const py::kwargs& kwargs) {
  render::RenderJob job;
  render::RenderSettings& s = job.settings;
  Keywords keywords(kwargs);
  keywords.path("scene", job.scene);
  keywords.integer("width", job.width);
  keywords.integer("height", job.height);
  keywords.integer("spp", job.spp);
  keywords.text("integrator", s.integrator);
  keywords.integer("light_samples", s.light_samples);
  keywords.text("light_strategy", s.light_strategy);
  keywords.text("hemisphere", s.hemisphere);
  keywords.integer("max_depth", s.max_depth);
  keywords.text("sampler", job.sampler);
  keywords.text("randomize", job.randomize, true);
  keywords.text("time_pattern", s.sampler.time_pattern, true);
  keywords.seed("seed", job.seed);
  keywords.threads("threads", s.threads);
  keywords.integer("passes", s.passes);
  keywords.flag("pixel_centers", s.pixel_centers);
  keywords.flag("reference", job.reference);
  keywords.integer("reference_spp", job.reference_spp);
  keywords.path("cache", job.cache);
  keywords.integer("frame", job.frame);
  bool with_variance = false;
  keywords.flag("with_variance", with_variance);
  keywords.finish();
  if (with_variance) job.variance = "True", job.variance_argument = "with_variance";
  render::prepare_render_job(job);
  const render::Scene scene = render::job_scene(job);
  render::RenderJobResult result;
  {
    InterruptibleRelease release;  // Ctrl-C: KeyboardInterrupt
    result = render::run_render_job(job, scene, {}, &interrupt_flag());
  }
  const render::Image& image = result.image;
  if (image.stopped) throw interrupted();  // Ctrl-C: KeyboardInterrupt, no partial image
  py::object variance = py::none();
  if (image.variance.size() == image.rgb.size()) variance = to_array(image.variance, image.width, image.height);
  return py::make_tuple(to_array(image.rgb, image.width, image.height), variance, image.samples, image.seconds,
                        result.cached);
}

/// compare(**kwargs): the keywords of stratum.compare(), read into a
/// CompareJob that the library checks, as the CLI's.
py::list compare_rows(const py::kwargs& kwargs) {
  render::CompareJob job;
  Keywords keywords(kwargs);
  keywords.path("scene", job.scene);
  keywords.text("builtin", job.builtin, true);
  keywords.text("configs", job.configs);
  keywords.integer("reference_spp", job.reference_spp);
  keywords.path("cache", job.options.cache_dir);
  keywords.real("equal_time", job.options.equal_time);
  keywords.path("variance_dir", job.options.variance_dir);
  keywords.integer("width", job.width);
  keywords.integer("height", job.height);
  keywords.threads("threads", job.threads);
  keywords.seed("seed", job.seed);
  keywords.integer("repeats", job.repeats);
  keywords.real("confidence", job.confidence);
  keywords.finish();
  render::CompareJobResult result;
  {
    InterruptibleRelease release;  // Ctrl-C: KeyboardInterrupt
    result = render::run_compare_job(job);
  }
  const render::RepeatedCompare& repeated = result.repeated;
  const unsigned repeats = repeated.repeats;
  const auto interval = [](const analysis::RatioInterval& i) { return py::make_tuple(i.low, i.high); };
  py::list out;
  for (std::size_t c = 0; c < repeated.summary.size(); ++c) {
    const render::CompareRow& r = repeated.summary[c];
    py::dict row(py::arg("label") = r.label, py::arg("spp") = r.samples, py::arg("passes") = r.passes,
                 py::arg("mse") = r.mse, py::arg("relative_mse") = r.relative_mse, py::arg("seconds") = r.seconds,
                 py::arg("efficiency") = r.efficiency, py::arg("mse_ratio") = r.mse_ratio,
                 py::arg("efficiency_ratio") = r.efficiency_ratio);
    if (!r.variance_path.empty()) row["variance"] = r.variance_path;
    row["scene_note"] = result.scene_note;               // what the comparison's scene leaves out ("" when nothing)
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
  m.def("render", &render_job,
        "Renders as stratum.render() (every argument by keyword): (image, variance or None, samples, seconds, "
        "cached)");
  m.def("compare", &compare_rows, "Compares as stratum.compare() (every argument by keyword): a dict per row");
  m.def("comparisons", [] {
    py::list list;
    for (const auto& [name, description] : render::builtin_comparisons())
      list.append(py::dict(py::arg("name") = name, py::arg("description") = description));
    return list;
  });
}

}  // namespace stratum::python
#endif
