/// Mitchell's comparison of patterns by random-edge discrepancy (mitchell_study.hpp).
#include "stratum/analysis/mitchell_study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "edge_discrepancy_detail.hpp"
#include "stratum/analysis/edge_discrepancy.hpp"
#include "stratum/analysis/spectrum.hpp"
#include "stratum/distributed.hpp"
#include "stratum/registry.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"

namespace stratum::analysis {

const std::vector<MitchellPattern>& mitchell_patterns() {
  static const std::vector<MitchellPattern> patterns{{"Zaremba", "zaremba", {}, ""},
                                                     {"jittered", "jittered", {}, ""},
                                                     {"Poisson disk", "poisson-disk", {{"periodic", "1"}}, ""},
                                                     {"N-rooks", "n-rooks", {}, ""},
                                                     {"random", "random", {}, ""}};
  return patterns;
}

std::string mitchell_pattern_id(const MitchellPattern& pattern) {
  return pattern.randomize.empty() ? pattern.sampler : pattern.sampler + ":" + pattern.randomize;
}

const MitchellCell& MitchellStudy::cell(const std::string& pattern, std::size_t requested) const {
  for (const auto& c : cells)
    if (c.pattern == pattern && c.requested == requested) return c;
  throw invalid_argument("cell", pattern + " at " + std::to_string(requested), "not part of this study");
}

namespace {

SamplerRequest request_for(const MitchellPattern& pattern, std::size_t n, std::uint64_t seed) {
  SamplerRequest request;
  request.params = pattern.params;
  request.n = n;
  request.d = 2;
  request.seed = seed;
  request.randomize = pattern.randomize;
  return request;
}

/// Every pattern of the study: Mitchell's five, then the extras, each
/// checked (2D, known randomizer, an id not seen before).
std::vector<MitchellPattern> study_patterns(const MitchellStudyOptions& options) {
  std::vector<MitchellPattern> patterns = mitchell_patterns();
  for (const auto& extra : options.extra_patterns) {
    const std::string id = mitchell_pattern_id(extra);
    const SamplerInfo& sampler = find_sampler(extra.sampler);
    require(sampler.min_dim <= 2 && sampler.max_dim >= 2, "extra_patterns", id, "a sampler that makes 2D points");
    for (const auto& known : patterns)
      require(mitchell_pattern_id(known) != id, "extra_patterns", id, "a pattern not already in the study");
    // The count is checked (and replaced where needed) by nearest_valid_count.
    if (!extra.randomize.empty() &&
        std::find(sampler.randomizers.begin(), sampler.randomizers.end(), extra.randomize) == sampler.randomizers.end())
      throw invalid_argument("extra_patterns", id, "a randomizer that " + sampler.name + " takes");
    patterns.push_back(extra);
  }
  return patterns;
}

/// The count nearest to `requested` that the sampler accepts (the smaller on a tie).
std::size_t nearest_valid_count(const MitchellPattern& pattern, std::size_t requested) {
  const SamplerInfo& sampler = find_sampler(pattern.sampler);
  auto valid = [&](std::size_t n) {
    if (n < 2) return false;
    try {
      validate_request(sampler, request_for(pattern, n, 0));
      return true;
    } catch (const invalid_argument&) {
      return false;
    }
  };
  for (std::size_t step = 0; step <= requested; ++step) {
    if (step <= requested && valid(requested - step)) return requested - step;
    if (valid(requested + step)) return requested + step;
  }
  throw invalid_argument("counts", std::to_string(requested),
                         "the sampler " + sampler.name + " takes " + sampler.counts);
}

/// printf-style formatting into a std::string (the analysis library has no fmt dependency).
template <class... Args>
std::string format(const char* pattern, Args... args) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, pattern, args...);
  return buffer;
}

MeanAndError mean_and_error(const std::vector<double>& values) {
  const double k = static_cast<double>(values.size());
  double sum = 0;
  for (double v : values) sum += v;
  const double mean = sum / k;
  double squares = 0;
  for (double v : values) squares += (v - mean) * (v - mean);
  return {mean, values.size() > 1 ? std::sqrt(squares / (k - 1) / k) : 0.0};
}

}  // namespace

MitchellStudy run_mitchell_study(const MitchellStudyOptions& options) {
  require(!options.counts.empty(), "counts", "''", "give at least one count");
  for (std::size_t n : options.counts) require(n >= 2 && n <= 1000000, "counts", n, "each count must be in [2, 10^6]");
  require(options.realizations >= 1 && options.realizations <= 100000, "realizations", options.realizations,
          "must be in [1, 10^5]");
  require(options.lines >= 1 && options.lines <= 100000000, "lines", options.lines, "must be in [1, 10^8]");
  MitchellStudy study;
  study.options = options;
  study.patterns = study_patterns(options);
  const auto& patterns = study.patterns;
  const std::size_t counts = options.counts.size(), k = options.realizations;
  for (const auto& pattern : patterns)
    for (std::size_t requested : options.counts) {
      MitchellCell cell;
      cell.pattern = mitchell_pattern_id(pattern);
      cell.requested = requested;
      cell.n = nearest_valid_count(pattern, requested);
      if (cell.n != requested)
        study.notes.push_back(cell.pattern + ": " + std::to_string(cell.n) + " points instead of " +
                              std::to_string(requested) + " (" + find_sampler(pattern.sampler).counts + ")");
      study.cells.push_back(std::move(cell));
    }
  std::size_t spectrum_count = options.spectrum_count;
  if (spectrum_count == 0) {
    spectrum_count = *std::min_element(options.counts.begin(), options.counts.end());
    for (std::size_t n : options.counts)
      if (n <= 1024) spectrum_count = std::max(spectrum_count, n);
  }
  // One task per (cell, realization); each writes only its own slots
  // (rms, mean, max). A distributed job's processes each run their share.
  const std::size_t tasks = study.cells.size() * k;
  std::vector<double> results(3 * tasks);
  std::vector<std::vector<double>> spectrum_points(patterns.size() * k);
  const std::size_t spectrum_column = static_cast<std::size_t>(
      std::find(options.counts.begin(), options.counts.end(), spectrum_count) - options.counts.begin());
  const auto realize = [&](std::size_t c, std::size_t r) {
    return generate_points(patterns[c / counts].sampler,
                           request_for(patterns[c / counts], study.cells[c].n, hash64(options.seed, r)));
  };
  const distributed::Dealt mine = distributed::dealt(tasks);  // round-robin: every cell shared
  edge_detail::parallel_ranges(mine.size(), options.threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t j = begin; j < end; ++j) {
      const std::size_t task = mine[j];
      const std::size_t c = task / k, r = task % k;
      const PointSet points = realize(c, r);
      const PointView view{points.data.get(), points.n, points.d};
      const RandomEdgeDiscrepancy d = random_edge_discrepancy(view, options.lines, hash64(options.seed, r, 1), 1);
      results[3 * task] = d.rms, results[3 * task + 1] = d.mean, results[3 * task + 2] = d.max;
      if (c % counts == spectrum_column && study.cells[c].requested == spectrum_count)
        spectrum_points[(c / counts) * k + r].assign(points.data.get(), points.data.get() + 2 * points.n);
    }
  });
  distributed::gather_dealt(results, tasks);
  if (distributed::size() > 1)  // the other processes' spectrum sets: generated again here (cheap beside the lines)
    for (std::size_t c = spectrum_column; c < study.cells.size(); c += counts)
      if (study.cells[c].requested == spectrum_count)
        for (std::size_t r = 0; r < k; ++r)
          if (spectrum_points[(c / counts) * k + r].empty()) {
            const PointSet points = realize(c, r);
            spectrum_points[(c / counts) * k + r].assign(points.data.get(), points.data.get() + 2 * points.n);
          }
  for (std::size_t c = 0; c < study.cells.size(); ++c) {
    std::vector<double> rms(k), mean(k), max(k);
    for (std::size_t r = 0; r < k; ++r) {
      rms[r] = results[3 * (c * k + r)];
      mean[r] = results[3 * (c * k + r) + 1];
      max[r] = results[3 * (c * k + r) + 2];
    }
    study.cells[c].rms = mean_and_error(rms);
    study.cells[c].mean = mean_and_error(mean);
    study.cells[c].max = mean_and_error(max);
    study.cells[c].rms_values = std::move(rms);
  }
  for (std::size_t p = 0; p < patterns.size(); ++p) {
    std::vector<PointView> views;
    for (std::size_t r = 0; r < k; ++r) {
      const auto& xs = spectrum_points[p * k + r];
      views.push_back({xs.data(), xs.size() / 2, 2});
    }
    const std::size_t n = views.front().n;
    const int max_frequency = static_cast<int>(std::ceil(3 * std::sqrt(static_cast<double>(n))));
    const RadialPower radial = radial_average(mean_periodogram(views, max_frequency, options.threads));
    study.spectra.push_back(
        {mitchell_pattern_id(patterns[p]), n, radial.frequency, radial.power, spectrum_points[p * k]});
  }
  return study;
}

std::string mitchell_table(const MitchellStudy& study) {
  std::string text = "random-edge discrepancy (RMS over " + std::to_string(study.options.lines) +
                     " lines; mean +- standard error over " + std::to_string(study.options.realizations) +
                     " realizations)\n";
  text += format("%-14s", "pattern");
  for (std::size_t n : study.options.counts) text += format("%22s", ("N = " + std::to_string(n)).c_str());
  text += "\n";
  for (const auto& pattern : study.patterns) {
    text += format("%-14s", pattern.label.c_str());
    for (std::size_t n : study.options.counts) {
      const MitchellCell& cell = study.cell(mitchell_pattern_id(pattern), n);
      text += format("%22s", format("%.4g +- %.2g", cell.rms.mean, cell.rms.error).c_str());
    }
    text += "\n";
  }
  for (const auto& note : study.notes) text += "note: " + note + "\n";
  return text;
}

}  // namespace stratum::analysis
