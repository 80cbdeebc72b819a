#pragma once
/// The optimizer of the rank tiles of sobol-bn, pmj02-bn and lattice-bn
/// (sequences/ranked_blue_noise.hpp).
///
/// Heitz et al. 2019 optimize per-pixel keys so that the errors of
/// neighbouring pixels, over a set of test integrands, are dissimilar;
/// Belcour & Heitz 2021 judge a tile by its "blur criterion", the variance
/// of the Gaussian-blurred error of random heavisides. Here that criterion
/// is the energy itself:
///
///   E = Σ_t Σ_pixels ((G ⊛ e_t)(pixel))²,
///
/// e_t the error image of test integrand t (a randomly oriented heaviside
/// in the pair's two dimensions, integrated by each pixel's block of spp
/// points, spp = 1, 2, 4, …, max_spp, each integrand with its own random
/// randomization of the base sequence (an Owen scramble of sobol or pmj02, or a
/// random shift), so the tile serves any seed), normalized
/// so each integrand weighs the same, and G the binomial filter
/// [1 4 6 4 1]/16 per axis (a Gaussian of σ = 1 pixel, exact in binary
/// floating point), on the torus, so the tile wraps seamlessly. A pixel's
/// errors depend on its rank alone, so ranks are only *swapped* between
/// pixels, as Heitz et al. swap keys: each integrand's total squared error
/// is fixed and a swap only moves error power between frequencies; E falls
/// when it moves to high ones. With K = G ⊛ G the change of a swap of pixels
/// a and b is 2 δ·(C_a − C_b) + 2 |δ|² (K(0) − K(a − b)), δ = e_b − e_a,
/// C = K ⊛ e, kept up to date on each accepted swap.
///
/// Structure (the default, "morton"): the ranks start as ZSobol's (Ahmed &
/// Wonka 2020) Morton order with each base-4 digit permuted per block, so
/// every aligned 2^l × 2^l block of pixels holds 4^l consecutive ranks —
/// neighbours' blocks together are an aligned block of the base sequence, a
/// net or lattice, under every randomization — and only the four ranks of a
/// 2 × 2 block are swapped, which keeps that. "free" starts from a random
/// permutation and swaps any two pixels: lower energy on the training
/// integrands, but the error of renders at 16 spp and more is less blue
/// (docs/blue-noise.md has the numbers).
///
/// Swaps are accepted by threshold accepting (Dueck & Scheuer 1990, the
/// deterministic variant of simulated annealing): ΔE < τ, τ falling
/// linearly to 0 over the run. Every random choice is a hash of the seed
/// and a counter, the work is single-threaded and the arithmetic contains
/// no libm call but sqrt (correctly rounded), so the table is the same bit
/// for bit on every run.
#include <cstdint>
#include <functional>
#include <vector>

#include "stratum/sequences/ranked_blue_noise.hpp"

namespace stratum::analysis {

struct BlueNoiseOptions {
  BlueNoiseBase base = BlueNoiseBase::sobol;  ///< the base sequence the ranks index
  std::uint32_t size = 128;                   ///< tile side in pixels, a power of 2 in [16, 256]
  std::uint32_t dims = 8;      ///< coordinates (dims / 2 pairs, each optimized on its own), even, [2, 64] (lattice: 32)
  std::uint64_t seed = 0;      ///< stratum::default_seed (the embedded tiles used --seed 1)
  std::uint32_t max_spp = 16;  ///< the sample counts optimized for: 1, 2, 4, …, max_spp (a power of 2, ≤ 256)
  std::uint32_t integrands = 32;                              ///< test integrands per sample count, [1, 1024]
  std::uint32_t sweeps = 256;                                 ///< swap proposals per pixel, [0, 100000]
  BlueNoiseStructure structure = BlueNoiseStructure::morton;  ///< Morton-structured ranks (default) or free swaps
};

/// What the optimizer reports per pair: E before and after, and E's
/// expectation for independent errors (white: divide by it, ≈ 1 at the start).
struct BlueNoisePairReport {
  double initial_energy = 0, final_energy = 0, white_energy = 0;
  std::uint64_t accepted = 0, proposed = 0;
};

/// Validates the options (stratum::invalid_argument naming the bad one).
void check_blue_noise_options(const BlueNoiseOptions& options);

/// The optimized tile; `progress(pair, pairs)` is called before each pair.
BlueNoiseTable optimize_blue_noise(const BlueNoiseOptions& options, std::vector<BlueNoisePairReport>* report = nullptr,
                                   const std::function<void(std::uint32_t, std::uint32_t)>& progress = {});

}  // namespace stratum::analysis
