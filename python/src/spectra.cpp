/// Spectra and pair correlation for Python (stratum.spectrum,
/// stratum.pair_correlation). Shapes are checked in python/stratum/spectra.py;
/// this side takes C-ordered float64 arrays and releases the GIL.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <vector>

#include "bindings.hpp"
#include "interruptible.hpp"
#include "stratum/analysis/blue_noise.hpp"
#include "stratum/analysis/geometry.hpp"
#include "stratum/analysis/image_spectrum.hpp"
#include "stratum/analysis/spectrum.hpp"
#include "stratum/util/error.hpp"

namespace py = pybind11;

namespace stratum::python {
namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
namespace sa = stratum::analysis;

/// image_spectrum.hpp on a (H, W) array of values.
py::dict image_spectrum(const Array& values) {
  if (values.ndim() != 2)
    throw invalid_argument("image", "an array of " + std::to_string(values.ndim()) + " dimensions",
                           "must have shape (height, width) (or (height, width, 3): its luminance)");
  const int height = static_cast<int>(values.shape(0)), width = static_cast<int>(values.shape(1));
  const std::vector<double> copy(values.data(), values.data() + values.size());
  sa::ImageSpectrum s;
  {
    InterruptibleRelease release;  // Ctrl-C: KeyboardInterrupt
    s = sa::image_spectrum(copy, width, height);
  }
  py::array_t<double> power({s.height, s.width});
  std::copy(s.power.begin(), s.power.end(), power.mutable_data());
  return py::dict(
      py::arg("power") = power, py::arg("low_frequency_power") = s.low_frequency_power,
      py::arg("variance") = s.variance,
      py::arg("radial") = py::dict(py::arg("frequency") = s.radial_frequency, py::arg("power") = s.radial_power));
}

/// image_spectrum.hpp's temporal spectrum of an (F, H, W) array of frames.
py::dict temporal_spectrum(const Array& values) {
  if (values.ndim() != 3)
    throw invalid_argument("frames", "an array of " + std::to_string(values.ndim()) + " dimensions",
                           "must have shape (frames, height, width) (or (frames, height, width, 3): luminance)");
  const auto frames = static_cast<std::size_t>(values.shape(0));
  const auto pixels = static_cast<std::size_t>(values.shape(1) * values.shape(2));
  std::vector<std::vector<double>> copy(frames);
  for (std::size_t t = 0; t < frames; ++t) copy[t].assign(values.data() + t * pixels, values.data() + (t + 1) * pixels);
  sa::TemporalSpectrum s;
  {
    InterruptibleRelease release;  // Ctrl-C: KeyboardInterrupt
    s = sa::temporal_spectrum(copy, static_cast<int>(values.shape(2)), static_cast<int>(values.shape(1)));
  }
  return py::dict(py::arg("frequency") = s.frequency, py::arg("power") = s.power,
                  py::arg("low_frequency_power") = s.low_frequency_power,
                  py::arg("lag1_correlation") = s.lag1_correlation, py::arg("variance") = s.variance);
}

/// analysis/blue_noise.hpp: the key file's bytes and the per-pair energies.
py::tuple optimize_blue_noise(const std::string& base, const std::string& structure, std::uint32_t size,
                              std::uint32_t dims, std::uint64_t seed, std::uint32_t max_spp, std::uint32_t integrands,
                              std::uint32_t sweeps) {
  sa::BlueNoiseOptions o{stratum::blue_noise_base_from(base, "base"),
                         size,
                         dims,
                         seed,
                         max_spp,
                         integrands,
                         sweeps,
                         stratum::blue_noise_structure_from(structure, "structure")};
  sa::check_blue_noise_options(o);
  std::vector<sa::BlueNoisePairReport> report;
  std::string bytes;
  {
    py::gil_scoped_release release;
    bytes = stratum::serialize_blue_noise_table(sa::optimize_blue_noise(o, &report));
  }
  py::list pairs;
  for (const auto& r : report)
    pairs.append(py::dict(py::arg("initial_energy") = r.initial_energy / r.white_energy,
                          py::arg("final_energy") = r.final_energy / r.white_energy, py::arg("accepted") = r.accepted,
                          py::arg("proposed") = r.proposed));
  return py::make_tuple(py::bytes(bytes), pairs);
}

/// realizations: a (K, n, d) array.
py::dict spectrum(const Array& realizations, int max_frequency, unsigned threads) {
  if (realizations.ndim() != 3)
    throw invalid_argument("x", "an array of " + std::to_string(realizations.ndim()) + " dimensions",
                           "must have shape (K, n, d)");
  const auto count = static_cast<std::size_t>(realizations.shape(0));
  const auto n = static_cast<std::size_t>(realizations.shape(1));
  const auto d = static_cast<std::size_t>(realizations.shape(2));
  std::vector<sa::PointView> views;
  for (std::size_t r = 0; r < count; ++r) views.push_back({realizations.data() + r * n * d, n, d});
  sa::Periodogram p;
  sa::RadialPower radial;
  sa::BlueNoiseFigures figures;
  {
    InterruptibleRelease release;  // Ctrl-C: KeyboardInterrupt
    p = sa::mean_periodogram(views, max_frequency, threads);
    radial = sa::radial_average(p);
    figures = sa::blue_noise_figures(radial);
  }
  const auto side = static_cast<py::ssize_t>(p.side());
  Array power = p.d == 1 ? Array({side}) : Array({side, side});
  std::copy(p.power.begin(), p.power.end(), power.mutable_data());
  py::dict radial_dict(py::arg("frequency") = radial.frequency, py::arg("radius") = radial.radius,
                       py::arg("power") = radial.power, py::arg("anisotropy_db") = radial.anisotropy_db,
                       py::arg("count") = radial.count);
  return py::dict(py::arg("power") = power, py::arg("max_frequency") = max_frequency,
                  py::arg("frequency_scale") = sa::radial_frequency_scale(n), py::arg("radial") = radial_dict,
                  py::arg("nyquist") = figures.effective_nyquist,
                  py::arg("nyquist_is_lower_bound") = figures.nyquist_is_lower_bound,
                  py::arg("oscillation") = figures.oscillation,
                  py::arg("oscillation_window") = py::make_tuple(figures.oscillation_from, figures.oscillation_to),
                  py::arg("realizations") = count);
}

py::dict pair_correlation(const Array& x, const std::vector<double>& radii, double sigma, unsigned threads) {
  if (x.ndim() != 2)
    throw invalid_argument("x", "an array of " + std::to_string(x.ndim()) + " dimensions", "must have shape (n, d)");
  const sa::PointView view{x.data(), static_cast<std::size_t>(x.shape(0)), static_cast<std::size_t>(x.shape(1))};
  sa::PairCorrelation g;
  {
    InterruptibleRelease release;  // Ctrl-C: KeyboardInterrupt
    g = sa::pair_correlation(view, radii, sigma, threads);
  }
  return py::dict(py::arg("r") = g.radius, py::arg("g") = g.g, py::arg("sigma") = g.sigma);
}

}  // namespace

void bind_spectra(py::module_& m) {
  m.def("_spectrum", &spectrum, py::arg("realizations"), py::arg("max_frequency"), py::arg("threads"));
  m.def("_image_spectrum", &image_spectrum, py::arg("values"));
  m.def("_temporal_spectrum", &temporal_spectrum, py::arg("values"));
  m.def("_optimize_blue_noise", &optimize_blue_noise, py::arg("base"), py::arg("structure"), py::arg("size"),
        py::arg("dims"), py::arg("seed"), py::arg("max_spp"), py::arg("integrands"), py::arg("sweeps"));
  m.def("_pair_correlation", &pair_correlation, py::arg("x"), py::arg("radii"), py::arg("sigma"), py::arg("threads"));
  m.def("_default_pair_correlation_grid", [](std::size_t n, std::size_t d, std::size_t count) {
    const sa::PairCorrelation grid = sa::default_pair_correlation_grid(n, d, count);
    return py::make_tuple(grid.radius, grid.sigma);
  });
}

}  // namespace stratum::python
