/// The key-tile optimizer (analysis/blue_noise.hpp). Compiled with
/// -ffp-contract=off (CMakeLists.txt): no fused multiply-adds, so every
/// machine computes the same energies and the same swaps.
#include "stratum/analysis/blue_noise.hpp"

#include <array>
#include <bit>
#include <cmath>
#include <string>

#include "stratum/memory.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"
#include "stratum/util/interrupt.hpp"

namespace stratum::analysis {
namespace {

constexpr std::uint64_t tag_ranks = 0x626e'7261'6e6bULL;     // "bnrank"
constexpr std::uint64_t tag_integrand = 0x626e'696e'74ULL;   // "bnint"
constexpr std::uint64_t tag_proposal = 0x626e'7072'6f70ULL;  // "bnprop"
constexpr int radius = 4;                                    // of K = G ⊛ G
/// τ0 as a fraction of the mean |ΔE| of the first proposals (0.1 ended
/// lower than greedy descent, 0 and larger fractions higher, on 64 × 64).
constexpr double threshold_fraction = 0.1;
constexpr double binomial8[2 * radius + 1] = {1, 8, 28, 56, 70, 56, 28, 8, 1};

/// K(dx, dy) for |dx|, |dy| ≤ 4: the binomial filter of order 8 per axis
/// (G ⊛ G with G = [1 4 6 4 1] / 16), every value a dyadic rational.
struct Kernel {
  std::array<double, (2 * radius + 1) * (2 * radius + 1)> w{};
  Kernel() {
    for (int dy = -radius; dy <= radius; ++dy)
      for (int dx = -radius; dx <= radius; ++dx)
        w[std::size_t((dy + radius) * (2 * radius + 1) + dx + radius)] =
            binomial8[dx + radius] * binomial8[dy + radius] / 65536.0;
  }
  double at(int dx, int dy) const noexcept {
    if (dx < -radius || dx > radius || dy < -radius || dy > radius) return 0;
    return w[std::size_t((dy + radius) * (2 * radius + 1) + dx + radius)];
  }
};

/// A test integrand: the heaviside [n · (x − c) > 0] of a random centre c in
/// the square and an isotropic random normal n (drawn in the unit disc, so
/// no trigonometry), with its own randomization keys of the shared sequence.
struct Heaviside {
  double cx, cy, nx, ny;
  std::uint64_t kx, ky;
};

Heaviside make_heaviside(std::uint64_t seed, std::uint32_t pair, std::uint32_t level, std::uint32_t t) {
  const std::uint64_t key = hash64(seed, tag_integrand, pair, level, t);
  Heaviside h{bits_to_double(hash64(key, 0)), bits_to_double(hash64(key, 1)), 0, 0, hash64(key, 2), hash64(key, 3)};
  for (std::uint64_t attempt = 0;; ++attempt) {
    const double x = 2 * bits_to_double(hash64(key, 4, attempt)) - 1,
                 y = 2 * bits_to_double(hash64(key, 5, attempt)) - 1;
    const double r2 = x * x + y * y;
    if (r2 > 1e-6 && r2 <= 1) {
      h.nx = x, h.ny = y;
      return h;
    }
  }
}

/// Wrapped coordinate on the torus of side n.
inline std::uint32_t wrap(std::int64_t v, std::uint32_t n) noexcept {
  const std::int64_t m = v % std::int64_t{n};
  return static_cast<std::uint32_t>(m < 0 ? m + n : m);
}

/// One pair's optimization: returns its ranks (one per pixel) and fills report.
std::vector<std::uint16_t> optimize_pair(const BlueNoiseOptions& o, std::uint32_t pair, BlueNoisePairReport& report) {
  const std::uint32_t s = o.size;
  const std::size_t n = std::size_t{s} * s;
  const unsigned levels = static_cast<unsigned>(std::countr_zero(o.max_spp)) + 1;
  const std::size_t m = std::size_t{levels} * o.integrands;  // test columns

  std::vector<std::uint16_t> ranks(n);
  if (o.structure == BlueNoiseStructure::morton) {
    // Morton ranks: the pixels of every aligned 2^l × 2^l block hold 4^l consecutive
    // ranks (so neighbours' blocks together are an aligned block of the sequence, a
    // net), each base-4 digit permuted per block as ZSobol does (Ahmed & Wonka 2020).
    const unsigned levels_of_tile = static_cast<unsigned>(std::countr_zero(s));
    for (std::size_t p = 0; p < n; ++p) {
      const std::uint32_t x = std::uint32_t(p % s), y = std::uint32_t(p / s);
      std::uint32_t rank = 0;
      for (unsigned l = 0; l < levels_of_tile; ++l) {
        const unsigned digit = ((x >> l) & 1u) | (((y >> l) & 1u) << 1);
        const std::uint64_t block = (std::uint64_t{y >> (l + 1)} << 32) | (x >> (l + 1));
        // a permutation of the four digits from a hash of (seed, pair, level, block)
        const std::uint64_t h = hash64(o.seed, tag_ranks, pair, l, block);
        std::uint8_t perm[4] = {0, 1, 2, 3};
        for (unsigned i = 3; i > 0; --i) std::swap(perm[i], perm[(h >> (8 * i)) % (i + 1)]);
        rank |= std::uint32_t{perm[digit]} << (2 * l);
      }
      ranks[p] = static_cast<std::uint16_t>(rank);
    }
  } else {
    // The ranks start as a random permutation (Fisher–Yates, hashed draws): white.
    for (std::size_t p = 0; p < n; ++p) ranks[p] = static_cast<std::uint16_t>(p);
    for (std::size_t p = n - 1; p > 0; --p)
      std::swap(ranks[p], ranks[uniform_below(p + 1, o.seed, tag_ranks, pair, p)]);
  }

  // e[p·m + c]: the error of pixel p's key on column c = level·T + t.
  std::vector<double> e(n * m), conv(n * m, 0.0);
  const RankedBase base(o.base);
  for (unsigned level = 0; level < levels; ++level) {
    const std::uint32_t spp = 1u << level;
    for (std::uint32_t t = 0; t < o.integrands; ++t) {
      const Heaviside h = make_heaviside(o.seed, pair, level, t);
      const std::size_t c = std::size_t{level} * o.integrands + t;
      double mean = 0;
      for (std::size_t p = 0; p < n; ++p) {
        // pixel p's points: block ranks[p] of the scrambled sequence
        std::uint32_t inside = 0;
        for (std::uint32_t i = 0; i < spp; ++i) {
          const std::uint64_t index = std::uint64_t{ranks[p]} * spp + i;
          const std::array<std::uint64_t, 2> bits = base.bits(pair, index, h.kx, h.ky);
          const double x = bits_to_double(bits[0]), y = bits_to_double(bits[1]);
          inside += h.nx * (x - h.cx) + h.ny * (y - h.cy) > 0;
        }
        e[p * m + c] = double(inside) / double(spp);
        mean += e[p * m + c];
      }
      // Centred and scaled to unit mean square (a constant column stays 0):
      // the integral drops out, as swaps keep every column's sum.
      mean /= double(n);
      double square = 0;
      for (std::size_t p = 0; p < n; ++p) square += (e[p * m + c] - mean) * (e[p * m + c] - mean);
      const double scale = square > 0 ? 1.0 / std::sqrt(square / double(n)) : 0.0;
      for (std::size_t p = 0; p < n; ++p) e[p * m + c] = (e[p * m + c] - mean) * scale;
    }
  }

  const Kernel kernel;
  const auto add_kernel = [&](std::uint32_t px, std::uint32_t py, const double* delta, double sign) {
    for (int dy = -radius; dy <= radius; ++dy)
      for (int dx = -radius; dx <= radius; ++dx) {
        const double w = sign * kernel.at(dx, dy);
        double* row = &conv[(std::size_t{wrap(std::int64_t{py} + dy, s)} * s + wrap(std::int64_t{px} + dx, s)) * m];
        for (std::size_t c = 0; c < m; ++c) row[c] += w * delta[c];
      }
  };
  for (std::size_t p = 0; p < n; ++p) add_kernel(std::uint32_t(p % s), std::uint32_t(p / s), &e[p * m], 1.0);
  const auto energy = [&] {
    double sum = 0;
    for (std::size_t i = 0; i < n * m; ++i) sum += e[i] * conv[i];
    return sum;
  };
  const double k0 = kernel.at(0, 0);
  report.white_energy = k0 * double(n) * double(m);  // i.i.d. unit-variance errors: N·K(0) per column
  report.initial_energy = energy();

  const std::uint64_t proposals = std::uint64_t{o.sweeps} * n;
  std::vector<double> delta(m);
  // ΔE of swapping a and b (δ = e_b − e_a, in `delta`).
  const auto change = [&](std::size_t a, std::size_t b, int dx, int dy) {
    const double* ea = &e[a * m];
    const double* eb = &e[b * m];
    const double* ca = &conv[a * m];
    const double* cb = &conv[b * m];
    double cross = 0, square = 0;
    for (std::size_t c = 0; c < m; ++c) {
      const double d = eb[c] - ea[c];
      delta[c] = d;
      cross += d * (ca[c] - cb[c]);
      square += d * d;
    }
    return 2 * cross + 2 * square * (k0 - kernel.at(dx, dy));
  };
  double threshold = 0;
  std::uint64_t accepted = 0;
  for (std::uint64_t k = 0; k < proposals; ++k) {
    if ((k & 0xffff) == 0) check_interrupt();
    const std::uint64_t h = hash64(o.seed, tag_proposal, pair, k);
    const std::size_t a = static_cast<std::size_t>(((h & 0xffffffffu) * n) >> 32);
    const std::uint32_t ax = std::uint32_t(a % s), ay = std::uint32_t(a / s);
    int dx, dy;
    if ((h >> 32) & 1) {  // a near neighbour (within the kernel) or any pixel
      dx = int((h >> 33) % (2 * radius + 1)) - radius, dy = int((h >> 40) % (2 * radius + 1)) - radius;
    } else {
      dx = int(((h >> 33) & 0xffffu) * s >> 16), dy = int(((h >> 49) & 0x7fffu) * s >> 15);
    }
    if (o.structure ==
        BlueNoiseStructure::morton) {  // a sibling in the same aligned 2 × 2 block: the Morton structure stays
      dx = int((ax & ~1u) + ((h >> 33) & 1u)) - int(ax), dy = int((ay & ~1u) + ((h >> 34) & 1u)) - int(ay);
    }
    const std::uint32_t bx = wrap(std::int64_t{ax} + dx, s), by = wrap(std::int64_t{ay} + dy, s);
    const std::size_t b = std::size_t{by} * s + bx;
    if (b == a) continue;
    // The torus offset b − a in [−s/2, s/2) per axis, for K(a − b).
    const auto torus = [s](std::int64_t d) { return int(d >= std::int64_t(s + 1) / 2 ? d - s : d); };
    const int ox = torus(std::int64_t(bx) - ax < 0 ? std::int64_t(bx) - ax + s : std::int64_t(bx) - ax);
    const int oy = torus(std::int64_t(by) - ay < 0 ? std::int64_t(by) - ay + s : std::int64_t(by) - ay);
    const double d_energy = change(a, b, ox, oy);
    if (k < 1024) {  // calibration: τ0 from the first 1024 proposals (none accepted)
      threshold += std::abs(d_energy) / 1024.0 * threshold_fraction;
      continue;
    }
    const double tau = threshold * (1.0 - double(k) / double(proposals));
    if (!(d_energy < tau)) continue;
    ++accepted;
    add_kernel(ax, ay, delta.data(), 1.0);
    add_kernel(bx, by, delta.data(), -1.0);
    for (std::size_t c = 0; c < m; ++c) std::swap(e[a * m + c], e[b * m + c]);
    std::swap(ranks[a], ranks[b]);
  }
  report.final_energy = energy();
  report.accepted = accepted;
  report.proposed = proposals;
  return ranks;
}

}  // namespace

void check_blue_noise_options(const BlueNoiseOptions& o) {
  require(o.size >= 16 && o.size <= 256 && std::has_single_bit(o.size), "size", o.size,
          "must be a power of 2 in [16, 256] (the tile's side in pixels)");
  const std::uint32_t max_dims = blue_noise_max_dims(o.base);
  require(
      o.dims >= 2 && o.dims <= max_dims && o.dims % 2 == 0, "dims", o.dims,
      "must be an even integer in [2, " + std::to_string(max_dims) + "] (base " + blue_noise_base_name(o.base) + ")");
  require(o.max_spp >= 1 && o.max_spp <= 256 && std::has_single_bit(o.max_spp), "max-spp", o.max_spp,
          "must be a power of 2 in [1, 256]");
  require(o.integrands >= 1 && o.integrands <= 1024, "integrands", o.integrands, "must be an integer in [1, 1024]");
  require(o.sweeps <= 100000, "sweeps", o.sweeps, "must be an integer in [0, 100000]");
}

BlueNoiseTable optimize_blue_noise(const BlueNoiseOptions& o, std::vector<BlueNoisePairReport>* report,
                                   const std::function<void(std::uint32_t, std::uint32_t)>& progress) {
  check_blue_noise_options(o);
  const std::size_t n = std::size_t{o.size} * o.size;
  const unsigned levels = static_cast<unsigned>(std::countr_zero(o.max_spp)) + 1;
  require_memory(2 * n * levels * o.integrands * sizeof(double), "the optimizer's error images");
  BlueNoiseTable table{o.base,   o.structure, o.size,
                       o.dims,   o.max_spp,   o.integrands,
                       o.sweeps, o.seed,      std::vector<std::uint16_t>(n * (o.dims / 2))};
  const std::uint32_t pairs = o.dims / 2;
  if (report) report->assign(pairs, {});
  for (std::uint32_t pair = 0; pair < pairs; ++pair) {
    if (progress) progress(pair, pairs);
    BlueNoisePairReport r;
    const std::vector<std::uint16_t> ranks = optimize_pair(o, pair, r);
    for (std::size_t p = 0; p < n; ++p) table.ranks[p * pairs + pair] = ranks[p];
    if (report) (*report)[pair] = r;
  }
  return table;
}

}  // namespace stratum::analysis
