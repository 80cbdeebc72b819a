#include "stratum/analysis/spectrum.hpp"

#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/info.h>
#include <oneapi/tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstring>
#include <limits>
#include <numbers>
#include <string>

#include "stratum/util/error.hpp"
#include "stratum/util/interrupt.hpp"

namespace stratum::analysis {
namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;
/// Points whose exponential tables are built together (a block's table,
/// 2·block·(2K+1) doubles, stays in the L2 cache for K up to a few hundred).
constexpr std::size_t point_block = 32;
/// The recurrence e_{k+1} = e_k·w is re-anchored on an exact sincos every this
/// many steps: each product adds about one ulp of phase error, so the error
/// stays below ~anchor_every·2^-53 regardless of K.
constexpr std::size_t anchor_every = 32;
/// Frequency rows summed together by one kernel call (each row's exponential
/// factor e^{−2πi ky y} is one complex number per point).
constexpr std::size_t rows_per_group = 4;
/// Most rows handled by one oneTBB task: the per-point x-tables are built once
/// per task and reused for all its rows, so larger tasks build fewer tables;
/// with several threads tasks shrink (to a multiple of rows_per_group) so that
/// every thread gets about four. Each row's sums do not depend on which task
/// or group holds it, so the result is the same for any task size.
constexpr std::size_t max_rows_per_task = 32;

/// exp(−2πi·cycles), with the phase reduced to [0, 1) first so large
/// frequencies lose no accuracy in the sine and cosine.
inline void unit_phasor(double cycles, double& re, double& im) {
  const double fraction = cycles - std::floor(cycles);
  const double angle = two_pi * fraction;
  re = std::cos(angle);
  im = -std::sin(angle);
}

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define STRATUM_SPECTRUM_CLONES \
  __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default"), optimize("fp-contract=fast")))
#else
#define STRATUM_SPECTRUM_CLONES
#endif

/// For one group of rows_per_group rows and a block of `count` points:
/// acc[g][t] += Σ_b c[b][g] · e[b][t] over `width` columns. Eight columns at a
/// time, the group's 64 partial sums stay in registers over the whole block,
/// so the inner loop only loads (no stores); each column's sum runs over the
/// points in the same order whatever the thread count.
/// c layout: c[b * c_stride + g]; e layout: e[b * e_stride + t];
/// acc layout: [row g][re | im][column], rows `stride` apart.
STRATUM_SPECTRUM_CLONES void accumulate_group(std::size_t count, std::size_t width, std::size_t stride,
                                              const double* __restrict c_re, const double* __restrict c_im,
                                              std::size_t c_stride, const double* __restrict e_re,
                                              const double* __restrict e_im, std::size_t e_stride,
                                              double* __restrict acc) {
  // GCC vector extension: eight doubles, one AVX-512 register (two AVX2 or
  // four SSE2 registers in the other clones); a scalar operand is broadcast.
  typedef double lane8 __attribute__((vector_size(64)));
  constexpr std::size_t lanes = 8;
  constexpr std::size_t groups = rows_per_group;
  std::size_t t0 = 0;
  for (; t0 + lanes <= width; t0 += lanes) {
    lane8 sum_re[groups], sum_im[groups];
    for (std::size_t g = 0; g < groups; ++g) {
      std::memcpy(&sum_re[g], acc + 2 * g * stride + t0, sizeof(lane8));
      std::memcpy(&sum_im[g], acc + (2 * g + 1) * stride + t0, sizeof(lane8));
    }
    for (std::size_t b = 0; b < count; ++b) {
      lane8 er, ei;
      std::memcpy(&er, e_re + b * e_stride + t0, sizeof(lane8));
      std::memcpy(&ei, e_im + b * e_stride + t0, sizeof(lane8));
      for (std::size_t g = 0; g < groups; ++g) {  // four multiply-adds where the clone has FMA
        const double cr = c_re[b * c_stride + g], ci = c_im[b * c_stride + g];
        sum_re[g] += cr * er;
        sum_re[g] -= ci * ei;
        sum_im[g] += cr * ei;
        sum_im[g] += ci * er;
      }
    }
    for (std::size_t g = 0; g < groups; ++g) {
      std::memcpy(acc + 2 * g * stride + t0, &sum_re[g], sizeof(lane8));
      std::memcpy(acc + (2 * g + 1) * stride + t0, &sum_im[g], sizeof(lane8));
    }
  }
  for (; t0 < width; ++t0)  // the last width % 8 columns
    for (std::size_t b = 0; b < count; ++b) {
      const double er = e_re[b * e_stride + t0], ei = e_im[b * e_stride + t0];
      for (std::size_t g = 0; g < groups; ++g) {
        const double cr = c_re[b * c_stride + g], ci = c_im[b * c_stride + g];
        acc[2 * g * stride + t0] += cr * er - ci * ei;
        acc[(2 * g + 1) * stride + t0] += cr * ei + ci * er;
      }
    }
}

/// Fills e[b·width + t] = exp(−2πi (t − K) x_b) for the block's points and
/// t = 0..2K by the recurrence, anchored exactly every anchor_every steps.
/// The point loop is innermost: each point's recurrence is a chain of
/// dependent complex products, and running the block's chains side by side
/// hides their latency.
void fill_exponentials(const PointView& points, std::size_t begin, std::size_t count, int max_frequency,
                       std::size_t width, double* e_re, double* e_im) {
  double step_re[point_block], step_im[point_block];
  for (std::size_t b = 0; b < count; ++b) unit_phasor(points(begin + b, 0), step_re[b], step_im[b]);
  for (std::size_t t = 0; t < width; ++t) {
    if (t % anchor_every == 0) {
      const double k = static_cast<double>(static_cast<long long>(t) - max_frequency);
      for (std::size_t b = 0; b < count; ++b)
        unit_phasor(k * points(begin + b, 0), e_re[b * width + t], e_im[b * width + t]);
      continue;
    }
    for (std::size_t b = 0; b < count; ++b) {
      const double re = e_re[b * width + t - 1], im = e_im[b * width + t - 1];
      e_re[b * width + t] = re * step_re[b] - im * step_im[b];
      e_im[b * width + t] = re * step_im[b] + im * step_re[b];
    }
  }
}

/// Adds |S(kx, ky)|²/N of one realization to `sum` for rows ky = 0..rows−1
/// (row ky stored at sum[(ky + row_offset)·width + kx + K]). d = 1: one row, no y.
void add_rows(const PointView& points, int max_frequency, std::size_t rows, std::size_t row_offset,
              std::vector<double>& sum, unsigned threads) {
  const std::size_t width = static_cast<std::size_t>(2 * max_frequency + 1);
  const std::size_t workers =
      threads == 0 ? static_cast<std::size_t>(oneapi::tbb::info::default_concurrency()) : std::size_t{threads};
  std::size_t rows_per_task = (rows + 4 * workers - 1) / (4 * workers);
  rows_per_task = std::clamp<std::size_t>((rows_per_task + rows_per_group - 1) / rows_per_group * rows_per_group,
                                          rows_per_group, max_rows_per_task);
  const std::size_t tasks = (rows + rows_per_task - 1) / rows_per_task;
  const double inverse_n = 1.0 / static_cast<double>(points.n);
  auto run_task = [&](std::size_t task) {
    const std::size_t first_row = task * rows_per_task;
    const std::size_t task_rows = std::min(rows_per_task, rows - first_row);
    const std::size_t groups = (task_rows + rows_per_group - 1) / rows_per_group;
    const std::size_t group_doubles = 2 * rows_per_group * width;
    std::vector<double> acc(groups * group_doubles, 0.0);
    std::vector<double> table_re(point_block * width), table_im(point_block * width);
    std::vector<double> row_re(point_block * groups * rows_per_group), row_im(row_re.size());
    for (std::size_t begin = 0; begin < points.n; begin += point_block) {
      const std::size_t count = std::min(point_block, points.n - begin);
      fill_exponentials(points, begin, count, max_frequency, width, table_re.data(), table_im.data());
      for (std::size_t b = 0; b < count; ++b) {
        const std::size_t i = begin + b;
        for (std::size_t r = 0; r < groups * rows_per_group; ++r) {
          double cr = 0, ci = 0;  // rows past the task's end get weight 0
          if (r < task_rows) {
            if (points.d == 1) {
              cr = 1;
            } else {
              unit_phasor(static_cast<double>(first_row + r) * points(i, 1), cr, ci);
            }
          }
          row_re[b * groups * rows_per_group + r] = cr;
          row_im[b * groups * rows_per_group + r] = ci;
        }
      }
      for (std::size_t g = 0; g < groups; ++g) {
        const std::size_t c = g * rows_per_group;
        accumulate_group(count, width, width, &row_re[c], &row_im[c], groups * rows_per_group, table_re.data(),
                         table_im.data(), width, &acc[g * group_doubles]);
      }
    }
    for (std::size_t r = 0; r < task_rows; ++r) {
      const double* re = &acc[(r / rows_per_group) * group_doubles + 2 * (r % rows_per_group) * width];
      const double* im = re + width;
      double* out = &sum[(first_row + r + row_offset) * width];
      for (std::size_t t = 0; t < width; ++t) out[t] += (re[t] * re[t] + im[t] * im[t]) * inverse_n;
    }
  };
  if (threads == 1 || tasks == 1) {
    for (std::size_t task = 0; task < tasks; ++task) {
      check_interrupt();
      run_task(task);
    }
    return;
  }
  oneapi::tbb::task_arena arena(threads == 0 ? oneapi::tbb::task_arena::automatic : static_cast<int>(threads));
  arena.execute([&] {
    oneapi::tbb::parallel_for(std::size_t{0}, tasks, [&](std::size_t task) {
      check_interrupt();
      run_task(task);
    });
  });
}

void check_realizations(const std::vector<PointView>& realizations, int max_frequency) {
  require(!realizations.empty(), "realizations", 0, "at least one point set is needed");
  const PointView& first = realizations.front();
  require(first.d == 1 || first.d == 2, "d", first.d, "spectra are defined here for d = 1 or 2");
  for (std::size_t r = 0; r < realizations.size(); ++r) {
    const PointView& points = realizations[r];
    require(points.d == first.d, "d of realization " + std::to_string(r), points.d,
            "every realization must have d = " + std::to_string(first.d));
    require(points.n == first.n, "n of realization " + std::to_string(r), points.n,
            "every realization must have n = " + std::to_string(first.n));
    check_unit_cube(points);
  }
  require(max_frequency >= 1, "max_frequency", max_frequency, "must be at least 1");
  const double side = 2.0 * static_cast<double>(max_frequency) + 1.0;
  const double values = first.d == 1 ? side : side * side;
  require(values <= static_cast<double>(max_periodogram_values()), "max_frequency", max_frequency,
          "the frequency grid (2K+1)^d must have at most 2^25 values (K ≤ " +
              std::to_string(first.d == 1 ? (max_periodogram_values() - 1) / 2 : 2896) +
              " for d = " + std::to_string(first.d) + ")");
}

Periodogram empty_periodogram(const std::vector<PointView>& realizations, int max_frequency) {
  Periodogram result;
  result.max_frequency = max_frequency;
  result.d = realizations.front().d;
  result.points = realizations.front().n;
  result.realizations = realizations.size();
  const std::size_t side = result.side();
  result.power.assign(result.d == 1 ? side : side * side, 0.0);
  return result;
}

void divide_by_realizations(Periodogram& result) {
  const double inverse = 1.0 / static_cast<double>(result.realizations);
  for (double& p : result.power) p *= inverse;
}

}  // namespace

std::size_t max_periodogram_values() { return std::size_t{1} << 25; }

double radial_frequency_scale(std::size_t points) { return std::sqrt(static_cast<double>(points)); }

Periodogram mean_periodogram(const std::vector<PointView>& realizations, int max_frequency, unsigned threads) {
  check_realizations(realizations, max_frequency);
  Periodogram result = empty_periodogram(realizations, max_frequency);
  const std::size_t side = result.side();
  const std::size_t k = static_cast<std::size_t>(max_frequency);
  for (const PointView& points : realizations) {
    if (result.d == 1) {
      add_rows(points, max_frequency, 1, 0, result.power, threads);
    } else {
      // Rows ky = 0..K; the rows ky < 0 follow from P(−k) = P(k) (real points).
      add_rows(points, max_frequency, k + 1, k, result.power, threads);
    }
  }
  if (result.d == 2)
    for (std::size_t row = 0; row < k; ++row) {  // ky = row − K < 0 mirrors −ky
      const std::size_t mirror = 2 * k - row;
      for (std::size_t t = 0; t < side; ++t)
        result.power[row * side + t] = result.power[mirror * side + (side - 1 - t)];
    }
  divide_by_realizations(result);
  return result;
}

Periodogram mean_periodogram_reference(const std::vector<PointView>& realizations, int max_frequency) {
  check_realizations(realizations, max_frequency);
  Periodogram result = empty_periodogram(realizations, max_frequency);
  const int k = max_frequency;
  const int ky_min = result.d == 1 ? 0 : -k, ky_max = result.d == 1 ? 0 : k;
  for (const PointView& points : realizations)
    for (int ky = ky_min; ky <= ky_max; ++ky)
      for (int kx = -k; kx <= k; ++kx) {
        std::complex<double> s = 0;
        for (std::size_t i = 0; i < points.n; ++i) {
          const double phase = kx * points(i, 0) + (result.d == 2 ? ky * points(i, 1) : 0.0);
          s += std::exp(std::complex<double>(0.0, -two_pi * phase));
        }
        const std::size_t index = static_cast<std::size_t>(ky + k) * result.side() + static_cast<std::size_t>(kx + k);
        result.power[result.d == 1 ? static_cast<std::size_t>(kx + k) : index] +=
            std::norm(s) / static_cast<double>(points.n);
      }
  divide_by_realizations(result);
  return result;
}

RadialPower radial_average(const Periodogram& periodogram) {
  const int k = periodogram.max_frequency;
  require(k >= 1, "max_frequency", k, "must be at least 1");
  require(periodogram.d == 1 || periodogram.d == 2, "d", periodogram.d, "must be 1 or 2");
  require(
      periodogram.power.size() == (periodogram.d == 1 ? periodogram.side() : periodogram.side() * periodogram.side()),
      "power.size()", periodogram.power.size(), "must be (2K+1)^d");
  const std::size_t rings = static_cast<std::size_t>(k);
  // Rings over the half plane {ky > 0} ∪ {ky = 0, kx > 0}: the other half
  // repeats the same values (P(−k) = P(k)), which would bias the variance.
  std::vector<double> sum(rings + 1, 0.0), squares(rings + 1, 0.0), half_count(rings + 1, 0.0);
  auto ring_of = [](int kx, int ky) { return static_cast<std::size_t>(std::lround(std::hypot(kx, ky))); };
  const int ky_max = periodogram.d == 1 ? 0 : k;
  for (int pass = 0; pass < 2; ++pass)
    for (int ky = 0; ky <= ky_max; ++ky)
      for (int kx = (ky == 0 ? 1 : -k); kx <= k; ++kx) {
        const std::size_t r = ring_of(kx, ky);
        if (r < 1 || r > rings) continue;
        const double p = periodogram.at(kx, ky);
        if (pass == 0) {
          sum[r] += p;
          half_count[r] += 1;
        } else {
          const double deviation = p - sum[r] / half_count[r];
          squares[r] += deviation * deviation;
        }
      }
  RadialPower result;
  const double scale = periodogram.points > 0 ? radial_frequency_scale(periodogram.points) : 1.0;
  for (std::size_t r = 1; r <= rings; ++r) {
    const double mean = half_count[r] > 0 ? sum[r] / half_count[r] : std::numeric_limits<double>::quiet_NaN();
    double anisotropy = std::numeric_limits<double>::quiet_NaN();
    if (half_count[r] >= 2 && mean > 0)
      anisotropy = 10.0 * std::log10(squares[r] / (half_count[r] - 1) / (mean * mean));
    result.radius.push_back(static_cast<double>(r));
    result.frequency.push_back(static_cast<double>(r) / scale);
    result.power.push_back(mean);
    result.anisotropy_db.push_back(anisotropy);
    result.count.push_back(2 * half_count[r]);
  }
  result.points = periodogram.points;
  return result;
}

BlueNoiseFigures blue_noise_figures(const RadialPower& radial) {
  BlueNoiseFigures figures;
  const std::size_t rings = radial.power.size();
  require(rings >= 1 && radial.count.size() == rings && radial.radius.size() == rings, "radial", rings,
          "needs at least one ring with its radius and count");
  const double scale = radial.points > 0 ? radial_frequency_scale(radial.points) : 1.0;
  // Cumulative power: the mean of P over every frequency 0 < |k| ≤ r.
  std::vector<double> cumulative(rings);
  double weighted = 0, frequencies = 0;
  for (std::size_t r = 0; r < rings; ++r) {
    weighted += radial.count[r] * radial.power[r];
    frequencies += radial.count[r];
    cumulative[r] = weighted / frequencies;
  }
  std::size_t rise = 0;  // first ring whose cumulative power exceeds 0.5
  while (rise < rings && !(cumulative[rise] > 0.5)) ++rise;
  figures.nyquist_is_lower_bound = rise == rings;
  std::size_t j = rise;
  while (j > 0 && !(cumulative[j - 1] < 0.1)) --j;
  // j rings (radii 1..j) at the bottom of the rise are below 0.1.
  const double zero_region = j == 0 ? 0.0 : radial.radius[j - 1];
  figures.effective_nyquist = 0.5 * zero_region / scale;

  std::size_t first = 0;  // first ring where the radial power reaches 0.98
  while (first < rings && !(radial.power[first] >= 0.98)) ++first;
  if (first == rings) {
    figures.oscillation = std::numeric_limits<double>::quiet_NaN();
    return figures;
  }
  const double from = radial.radius[first];
  const double to = std::min(from + 5.0 * scale, radial.radius[rings - 1]);
  double deviation = 0, area = 0;
  for (std::size_t r = first; r < rings && radial.radius[r] <= to; ++r) {
    deviation += radial.count[r] * (radial.power[r] - 1) * (radial.power[r] - 1);
    area += radial.count[r];
  }
  figures.oscillation = 10.0 * std::sqrt(deviation / area);
  figures.oscillation_from = from / scale;
  figures.oscillation_to = to / scale;
  figures.window_is_cut = from + 5.0 * scale > radial.radius[rings - 1];
  return figures;
}

}  // namespace stratum::analysis
