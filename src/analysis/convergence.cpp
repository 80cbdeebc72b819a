/// Integration with registry samplers and convergence studies; see
/// src/analysis/include/stratum/analysis/convergence.hpp.
#include "stratum/analysis/convergence.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <boost/math/distributions/students_t.hpp>

#include <algorithm>
#include <bit>
#include <charconv>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "stratum/distributed.hpp"
#include "stratum/estimators/efficiency.hpp"
#include "stratum/estimators/rqmc.hpp"
#include "stratum/estimators/running_stats.hpp"
#include "stratum/registry.hpp"
#include "stratum/registry/spec.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"
#include "stratum/util/interrupt.hpp"
#include "stratum/memory.hpp"

namespace stratum::analysis {

namespace {

constexpr unsigned max_threads = 1024;
constexpr unsigned max_runs = 1000000;

/// Mean of f over one generated point set, and the wall time it took.
struct RunOutcome {
  double estimate = 0;
  double seconds = 0;
  estimators::RunningStats values;  ///< only filled when asked (integrate with one run)
};

SamplerRequest sampler_request(const SamplerChoice& choice, std::uint64_t n, unsigned d, std::uint64_t seed,
                               unsigned threads) {
  SamplerRequest request;
  request.n = n;
  request.d = d;
  request.seed = seed;
  request.randomize = choice.randomize;
  request.params = choice.params;
  request.threads = threads;
  return request;
}

/// Checks the request against the sampler (name, d, randomizer, n) and
/// returns the randomizer it resolves to.
std::string check_sampler(const SamplerChoice& choice, std::uint64_t n, unsigned d) {
  const SamplerInfo& info = find_sampler(choice.name);
  return validate_request(info, sampler_request(choice, n, d, 0, 1));
}

RunOutcome run_once(const Integrand& integrand, const SamplerChoice& choice, std::uint64_t n, std::uint64_t seed,
                    unsigned threads, bool keep_values) {
  const auto start = std::chrono::steady_clock::now();
  const unsigned d = static_cast<unsigned>(integrand.dimension());
  const PointSet points = generate_points(choice.name, sampler_request(choice, n, d, seed, threads));
  std::vector<double> values(points.n);
  integrand.evaluate(points.data.get(), points.n, values.data());
  RunOutcome outcome;
  double sum = 0;
  for (double v : values) sum += v;
  if (keep_values)
    for (double v : values) outcome.values.add(v);
  outcome.estimate = sum / static_cast<double>(points.n);
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return outcome;
}

/// The memory guard (stratum/memory.hpp): `concurrent` runs at once, each
/// holding n points of d coordinates and their n integrand values.
void require_runs_memory(std::uint64_t concurrent, std::uint64_t n, unsigned d) {
  require_memory(double(concurrent) * double(n) * (double(d) + 1) * sizeof(double),
                 std::to_string(concurrent) + (concurrent == 1 ? " run" : " runs at once") + " of " +
                     std::to_string(n) + " x " + std::to_string(d) + " points and their integrand values");
}

std::uint64_t parse_count(std::string_view item, std::string_view whole) {
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(item.data(), item.data() + item.size(), value);
  if (item.empty() || error != std::errc() || end != item.data() + item.size() || value == 0)
    throw invalid_argument("n", whole.empty() ? "''" : std::string(whole),
                           "must be A:B (powers of two from A to B), A:B:F (A, A*F, ... up to B) or a comma "
                           "list of positive integers");
  return value;
}

}  // namespace

SamplerChoice parse_sampler_choice(std::string_view text) {
  SamplerSpec spec = parse_sampler_spec(text);
  return {std::move(spec.name), std::move(spec.randomize), std::move(spec.params)};
}

std::vector<std::uint64_t> parse_counts(std::string_view text) {
  std::vector<std::uint64_t> counts;
  if (text.find(':') != std::string_view::npos) {
    const std::size_t first = text.find(':');
    const std::size_t second = text.find(':', first + 1);
    const std::uint64_t low = parse_count(text.substr(0, first), text);
    const std::uint64_t high = parse_count(
        text.substr(first + 1, second == std::string_view::npos ? std::string_view::npos : second - first - 1), text);
    const std::uint64_t factor = second == std::string_view::npos ? 2 : parse_count(text.substr(second + 1), text);
    require(low <= high, "n", text, "the range A:B needs A <= B");
    require(factor >= 2, "n", text, "the factor F of A:B:F must be at least 2");
    if (second == std::string_view::npos)
      require(std::has_single_bit(low) && std::has_single_bit(high), "n", text,
              "A:B lists the powers of two from A to B, so both must be powers of two (or give A:B:F or a list)");
    for (std::uint64_t n = low; n <= high; n *= factor) {
      counts.push_back(n);
      if (n > high / factor) break;
    }
    return counts;
  }
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    counts.push_back(parse_count(
        text.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start), text));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  for (std::size_t k = 1; k < counts.size(); ++k)
    require(counts[k] > counts[k - 1], "n", text, "the list must be strictly increasing");
  return counts;
}

SlopeFit fit_log_log(std::span<const double> x, std::span<const double> y) {
  require(x.size() == y.size(), "y", y.size(), "needs one value per x (" + std::to_string(x.size()) + ")");
  require(x.size() >= 2, "points", x.size(), "a line needs at least 2 points");
  for (std::size_t i = 0; i < x.size(); ++i) {
    require(std::isfinite(x[i]) && x[i] > 0, "x[" + std::to_string(i) + "]", x[i], "must be positive and finite");
    require(std::isfinite(y[i]) && y[i] > 0, "y[" + std::to_string(i) + "]", y[i], "must be positive and finite");
  }
  const std::size_t m = x.size();
  double mean_x = 0, mean_y = 0;
  for (std::size_t i = 0; i < m; ++i) {
    mean_x += std::log(x[i]) / static_cast<double>(m);
    mean_y += std::log(y[i]) / static_cast<double>(m);
  }
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < m; ++i) {
    const double dx = std::log(x[i]) - mean_x;
    sxx += dx * dx;
    sxy += dx * (std::log(y[i]) - mean_y);
  }
  require(sxx > 0, "x", "(all equal)", "needs at least 2 distinct values");
  SlopeFit fit;
  fit.points = m;
  fit.slope = sxy / sxx;
  fit.intercept = mean_y - fit.slope * mean_x;
  if (m < 3) {
    fit.slope_standard_error = std::numeric_limits<double>::quiet_NaN();
  } else {
    double sse = 0;  // residual sum of squares of the fitted line
    for (std::size_t i = 0; i < m; ++i) {
      const double residual = std::log(y[i]) - (fit.intercept + fit.slope * std::log(x[i]));
      sse += residual * residual;
    }
    fit.slope_standard_error = std::sqrt(sse / static_cast<double>(m - 2) / sxx);
  }
  return fit;
}

SlopeInterval slope_interval(std::span<const double> x, std::span<const double> estimates, unsigned runs,
                             double confidence) {
  require(runs >= 3, "runs", runs, "must be at least 3 (a variance with one run left out needs 2)");
  require(estimates.size() == x.size() * runs, "estimates", estimates.size(),
          "needs runs = " + std::to_string(runs) + " values per count (" + std::to_string(x.size()) + " counts)");
  require(confidence > 0 && confidence < 1, "confidence", confidence,
          "must be a level strictly between 0 and 1, e.g. 0.95");
  const std::size_t m = x.size();
  double mean_x = 0, sxx = 0;
  for (double value : x) mean_x += std::log(value) / static_cast<double>(m);
  for (double value : x) sxx += (std::log(value) - mean_x) * (std::log(value) - mean_x);
  require(sxx > 0, "x", "(all equal)", "needs at least 2 distinct counts");
  // Per count: mean and sum of squared deviations, then the slope's weights.
  const double r = runs;
  std::vector<double> mean(m, 0.0), squares(m, 0.0), weight(m);
  for (std::size_t k = 0; k < m; ++k) {
    const double* cell = estimates.data() + k * runs;
    for (unsigned i = 0; i < runs; ++i) mean[k] += cell[i] / r;
    for (unsigned i = 0; i < runs; ++i) squares[k] += (cell[i] - mean[k]) * (cell[i] - mean[k]);
    weight[k] = (std::log(x[k]) - mean_x) / sxx;
  }
  auto log_variance = [&](double sum_of_squares, double count) {
    require(sum_of_squares > 0, "estimates", "(no spread)",
            "every count needs runs that differ, also with one left out");
    return std::log(sum_of_squares / (count - 1));
  };
  SlopeInterval interval;
  for (std::size_t k = 0; k < m; ++k) interval.slope += weight[k] * log_variance(squares[k], r);
  // Leaving run i out of count k: Σ (x − mean')² = squares − (x_i − mean)² · R / (R − 1).
  std::vector<double> left_out(runs, 0.0);
  for (std::size_t k = 0; k < m; ++k) {
    const double* cell = estimates.data() + k * runs;
    for (unsigned i = 0; i < runs; ++i) {
      const double deviation = cell[i] - mean[k];
      const double rest = std::max(squares[k] - deviation * deviation * r / (r - 1), 0.0);
      left_out[i] += weight[k] * log_variance(rest, r - 1);
    }
  }
  double left_out_mean = 0, spread = 0;
  for (double s : left_out) left_out_mean += s / r;
  for (double s : left_out) spread += (s - left_out_mean) * (s - left_out_mean);
  interval.standard_error = std::sqrt((r - 1) / r * spread);
  interval.confidence = confidence;
  const double t = boost::math::quantile(boost::math::students_t(r - 1), (1 + confidence) / 2);
  interval.low = interval.slope - t * interval.standard_error;
  interval.high = interval.slope + t * interval.standard_error;
  return interval;
}

namespace {
/// slope_interval, or NaN bounds where it cannot be formed: R = 2 runs, or
/// a count whose runs agree once one is left out.
SlopeInterval interval_or_nan(std::span<const double> x, std::span<const double> estimates, unsigned runs,
                              double confidence) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  try {
    if (runs >= 3) return slope_interval(x, estimates, runs, confidence);
  } catch (const invalid_argument& error) {
    if (error.argument() != "estimates") throw;
  }
  return {nan, nan, confidence, nan, nan};
}
}  // namespace

IntegrationResult integrate(const IntegrationRequest& request) {
  const auto integrand = make_integrand(request.integrand.name, request.integrand.d, request.integrand.params);
  const auto d = static_cast<unsigned>(integrand->dimension());
  require(request.n >= 1, "n", request.n, "must be a positive integer");
  require(request.runs >= 1 && request.runs <= max_runs, "runs", request.runs, "must be in [1, 1000000]");
  require(request.threads >= 1 && request.threads <= max_threads, "threads", request.threads, "must be in [1, 1024]");
  require(request.confidence > 0 && request.confidence < 1, "confidence", request.confidence,
          "must be a level strictly between 0 and 1, e.g. 0.95");
  IntegrationResult result;
  result.randomize = check_sampler(request.sampler, request.n, d);
  result.integrand = find_integrand(request.integrand.name).name;
  result.sampler = request.sampler.name;
  result.d = d;
  result.n = request.n;
  result.runs = request.runs;
  result.exact = integrand->exact();
  require_runs_memory(request.runs == 1 ? 1 : std::min<std::uint64_t>(request.threads, request.runs), request.n, d);
  const auto start = std::chrono::steady_clock::now();
  if (request.runs == 1) {
    // One point set: the standard error from its n values (i.i.d. formula).
    const RunOutcome outcome = run_once(*integrand, request.sampler, request.n, request.seed, request.threads, true);
    result.run_estimates = {outcome.estimate};
    result.estimate = outcome.estimate;
    result.standard_error = request.n >= 2 ? outcome.values.standard_error() : std::numeric_limits<double>::quiet_NaN();
    result.standard_error_kind = "iid";
    result.seconds_per_run = outcome.seconds;
  } else {
    // Independent randomizations, run r seeded with hash64(seed, r): the RQMC replicate estimate.
    // The runs are a job's items: a distributed job's processes each run their share.
    result.run_estimates.resize(request.runs);
    std::vector<double> run_seconds(request.runs);
    const distributed::Dealt mine = distributed::dealt(request.runs);
    tbb::task_arena arena(static_cast<int>(request.threads));
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mine.size(), 1),
                        [&](const tbb::blocked_range<std::size_t>& range) {
                          for (std::size_t j = range.begin(); j != range.end(); ++j) {
                            check_interrupt();
                            const std::size_t r = mine[j];
                            const RunOutcome outcome =
                                run_once(*integrand, request.sampler, request.n, hash64(request.seed, r), 1, false);
                            result.run_estimates[r] = outcome.estimate;
                            run_seconds[r] = outcome.seconds;
                          }
                        });
    });
    distributed::gather_dealt(result.run_estimates, request.runs);
    distributed::gather_dealt(run_seconds, request.runs);
    for (double s : run_seconds) result.seconds_per_run += s / request.runs;
    const auto replicates = estimators::rqmc_estimate(result.run_estimates);
    result.estimate = replicates.estimate;
    result.standard_error = replicates.standard_error;
    result.standard_error_kind = "replicates";
    // Runs that do not differ (a deterministic sampler or randomizer) say
    // nothing about the error: no standard error rather than a false 0.
    if (std::all_of(result.run_estimates.begin(), result.run_estimates.end(),
                    [&](double v) { return v == result.run_estimates.front(); })) {
      result.standard_error = std::numeric_limits<double>::quiet_NaN();
      result.standard_error_kind = "identical-runs";
    }
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.error = result.estimate - result.exact;
  // The Student-t interval: ν = runs − 1 over the replicates, n − 1 over one set's values.
  result.confidence = request.confidence;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  result.half_width = result.interval_low = result.interval_high = result.efficiency = nan;
  if (std::isfinite(result.standard_error)) {
    const double dof = request.runs >= 2 ? request.runs - 1.0 : static_cast<double>(request.n) - 1.0;
    const double t = boost::math::quantile(boost::math::students_t(dof), (1 + request.confidence) / 2);
    result.half_width = t * result.standard_error;
    result.interval_low = result.estimate - result.half_width;
    result.interval_high = result.estimate + result.half_width;
    // One run's variance: the replicates' (SE² · runs), or s²/n for one set.
    const double variance = result.standard_error * result.standard_error * (request.runs >= 2 ? request.runs : 1);
    result.seconds_per_run = std::max(result.seconds_per_run, 1e-9);  // a clock tick at least, as converge
    result.efficiency = estimators::efficiency(variance, result.seconds_per_run);
  }
  return result;
}

ConvergenceResult run_convergence(const ConvergenceRequest& request) {
  const auto integrand = make_integrand(request.integrand.name, request.integrand.d, request.integrand.params);
  const auto d = static_cast<unsigned>(integrand->dimension());
  require(!request.samplers.empty(), "samplers", "(none)", "give at least one sampler");
  require(!request.counts.empty(), "n", "(none)", "give at least one point count");
  require(request.runs >= 2 && request.runs <= max_runs, "runs", request.runs,
          "must be in [2, 1000000] (a variance needs at least 2 runs)");
  require(request.threads >= 1 && request.threads <= max_threads, "threads", request.threads, "must be in [1, 1024]");
  require(request.confidence > 0 && request.confidence < 1, "confidence", request.confidence,
          "must be a level strictly between 0 and 1, e.g. 0.95");
  for (std::size_t k = 0; k < request.counts.size(); ++k) {
    require(request.counts[k] >= 1, "n", request.counts[k], "must be a positive integer");
    if (k > 0) require(request.counts[k] > request.counts[k - 1], "n", request.counts[k], "N values must increase");
  }
  ConvergenceResult result;
  result.integrand = find_integrand(request.integrand.name).name;
  result.d = d;
  result.exact = integrand->exact();
  result.runs = request.runs;
  // The cells (sampler, N) to run: every count, or (skip_refused_counts)
  // the counts each sampler takes.
  struct Cell {
    std::size_t sampler;
    std::uint64_t n;
  };
  std::vector<Cell> cells;
  for (std::size_t s = 0; s < request.samplers.size(); ++s) {
    const SamplerChoice& choice = request.samplers[s];
    SamplerConvergence entry;
    entry.sampler = choice;
    std::size_t taken = 0;
    for (std::uint64_t n : request.counts) {
      try {
        entry.sampler.randomize = check_sampler(choice, n, d);
      } catch (const invalid_argument& error) {
        if (!request.skip_refused_counts || error.argument() != "n") throw;
        entry.skipped.push_back({n, error.what()});
        continue;
      }
      cells.push_back({s, n});
      ++taken;
    }
    if (taken == 0) {
      std::string listed;
      for (std::uint64_t n : request.counts) listed += (listed.empty() ? "" : ",") + std::to_string(n);
      throw invalid_argument("n", listed,
                             "sampler '" + choice.name + "' takes none of these counts (" +
                                 entry.skipped.front().reason + "); give --n with counts it takes");
    }
    result.samplers.push_back(std::move(entry));
  }

  // Every (sampler, N, run) is one task writing its own slot; the reduction
  // below reads the slots in a fixed order, so the numbers do not depend on
  // how TBB schedules the tasks.
  // The tasks are also a job's items: each process of a distributed job runs
  // its share, and every process then holds every slot.
  const std::size_t tasks = cells.size() * request.runs;
  std::uint64_t largest = 0;
  for (const Cell& cell : cells) largest = std::max(largest, cell.n);
  require_runs_memory(std::min<std::uint64_t>(request.threads, tasks), largest, d);
  std::vector<double> slots(2 * tasks);  // (estimate, seconds) of each task
  // Dealt round-robin: each process takes every K-th run of every cell, so
  // the costly cells (large N) are shared, not left to one process.
  const distributed::Dealt mine = distributed::dealt(tasks);
  tbb::task_arena arena(static_cast<int>(request.threads));
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mine.size(), 1),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        for (std::size_t j = range.begin(); j != range.end(); ++j) {
                          check_interrupt();
                          const std::size_t task = mine[j];
                          const Cell& cell = cells[task / request.runs];
                          const std::size_t r = task % request.runs;
                          const RunOutcome outcome = run_once(*integrand, result.samplers[cell.sampler].sampler, cell.n,
                                                              hash64(request.seed, cell.sampler, cell.n, r), 1, false);
                          slots[2 * task] = outcome.estimate;
                          slots[2 * task + 1] = outcome.seconds;
                        }
                      });
  });
  distributed::gather_dealt(slots, tasks);
  const auto estimate_of = [&](std::size_t task) { return slots[2 * task]; };
  const auto seconds_of = [&](std::size_t task) { return slots[2 * task + 1]; };

  for (std::size_t s = 0; s < result.samplers.size(); ++s) {
    auto& entry = result.samplers[s];
    std::vector<double> x, variances, mses, estimates;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      if (cells[c].sampler != s) continue;
      estimators::RunningStats spread, time;
      double error_sum = 0, squared_error_sum = 0;
      for (std::size_t r = 0; r < request.runs; ++r) {
        const std::size_t task = c * request.runs + r;
        const double error = estimate_of(task) - result.exact;
        spread.add(estimate_of(task));
        time.add(seconds_of(task));
        error_sum += error;
        squared_error_sum += error * error;
      }
      ConvergenceRow row;
      row.n = cells[c].n;
      row.mean_error = error_sum / request.runs;
      row.rmse = std::sqrt(squared_error_sum / request.runs);
      row.variance = spread.variance();
      row.seconds = std::max(time.mean(), 1e-9);  // a clock tick at least: efficiency stays finite
      for (std::size_t r = 0; r < request.runs; ++r) estimates.push_back(estimate_of(c * request.runs + r));
      row.efficiency = estimators::efficiency(row.variance, row.seconds);
      entry.rows.push_back(row);
      x.push_back(static_cast<double>(row.n));
      variances.push_back(row.variance);
      mses.push_back(row.rmse * row.rmse);
    }
    auto all_positive = [](const std::vector<double>& v) {
      for (double value : v)
        if (!(value > 0)) return false;
      return true;
    };
    if (x.size() >= 2 && all_positive(variances)) {
      entry.slope = fit_log_log(x, variances);
      entry.fitted = "variance";
      entry.interval = interval_or_nan(x, estimates, request.runs, request.confidence);
    } else if (x.size() >= 2 && all_positive(mses)) {
      entry.slope = fit_log_log(x, mses);
      entry.fitted = "mse";
    }
    if (entry.fitted != "variance") {
      constexpr double nan = std::numeric_limits<double>::quiet_NaN();
      entry.interval = {nan, nan, request.confidence, nan, nan};
    }
    if (entry.fitted.empty()) {
      entry.slope.slope = entry.slope.slope_standard_error = entry.slope.intercept =
          std::numeric_limits<double>::quiet_NaN();
      entry.fitted = "none";
    }
  }
  return result;
}

}  // namespace stratum::analysis
