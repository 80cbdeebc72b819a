// The core pixel sampler (pixel/pixel_sampler.hpp): each pixel's set has its
// technique's property, arrays stratify among themselves and continue the
// pixel's sequence, frames continue, pixels and dimensions are decorrelated
// (the renderer's draws against the core's: tests/render/core_draws_test.cpp).
#include "stratum/pixel/pixel_sampler.hpp"

#include <gtest/gtest.h>

#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <cstdint>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

#include "stratum/pixel/set_techniques.hpp"
#include "../sequences/zero_net.hpp"

namespace {

using namespace stratum;
using namespace stratum::pixel;
using Points = std::vector<std::array<double, 2>>;

template <class Technique>
Shared<Technique> shared_of(const Technique& technique, std::uint32_t spp, std::uint64_t seed = 7,
                            std::uint32_t frame = 0) {
  const std::optional<Shared<Technique>> shared = Shared<Technique>::make(technique, spp, seed, frame);
  EXPECT_TRUE(shared.has_value());
  return *shared;
}

/// Dimension `dimension` (a get_2d after `dimension` draws) of pixel (x, y), every sample.
template <class Technique>
Points pixel_set(const Shared<Technique>& shared, std::uint32_t x, std::uint32_t y, std::uint32_t dimension) {
  PixelSampler<Technique> sampler(&shared);
  Points points;
  for (std::uint32_t i = 0; i < shared.spp; ++i) {
    sampler.start_pixel_sample(x, y, i);
    for (std::uint32_t d = 0; d < dimension; ++d) sampler.get_1d();
    points.push_back(sampler.get_2d());
  }
  return points;
}

bool one_per_cell(const Points& points, int columns, int rows) {
  std::set<int> cells;
  for (const auto& p : points) cells.insert(int(p[0] * columns) * rows + int(p[1] * rows));
  return int(cells.size()) == columns * rows && int(points.size()) == columns * rows;
}

TEST(CorePixelSampler, StateIsSmallAndTriviallyCopyable) {
  static_assert(std::is_trivially_copyable_v<PixelSampler<SobolOwenHash>>);
  static_assert(std::is_trivially_copyable_v<PixelSampler<CmjTechnique>>);
  EXPECT_LE(sizeof(PixelSampler<SobolOwenHash>), 32u);  // a pointer and 24 bytes of state
  EXPECT_LE(sizeof(PixelSampler<CmjTechnique>), 32u);
}

TEST(CorePixelSampler, EachPixelsSetHasItsTechniquesProperty) {
  for (const std::uint32_t m : {2u, 4u, 6u}) {
    const auto sobol = shared_of(SobolOwenHash{}, 1u << m);
    const auto pmj = shared_of(Pmj02Technique{}, 1u << m);
    for (std::uint32_t dimension : {0u, 1u, 5u}) {
      EXPECT_TRUE(stratum::testing::is_zero_net(pixel_set(sobol, 3, 4, dimension))) << m << " " << dimension;
      EXPECT_TRUE(stratum::testing::is_zero_net(pixel_set(pmj, 3, 4, dimension))) << m << " " << dimension;
    }
  }
  for (const int k : {2, 3, 5}) {
    const auto jittered = shared_of(JitteredTechnique{}, k * k);
    const auto cmj = shared_of(CmjTechnique{}, k * k);
    for (std::uint32_t dimension : {0u, 3u}) {
      EXPECT_TRUE(one_per_cell(pixel_set(jittered, 1, 9, dimension), k, k));
      const Points set = pixel_set(cmj, 1, 9, dimension);
      EXPECT_TRUE(one_per_cell(set, k, k));      // one point per cell of the k × k grid
      EXPECT_TRUE(one_per_cell(set, k * k, 1));  // Latin in x …
      EXPECT_TRUE(one_per_cell(set, 1, k * k));  // … and in y
    }
  }
  // Unequal to the next dimension's and the next pixel's set.
  const auto sobol = shared_of(SobolOwenHash{}, 16);
  EXPECT_NE(pixel_set(sobol, 3, 4, 0), pixel_set(sobol, 3, 4, 1));
  EXPECT_NE(pixel_set(sobol, 3, 4, 0), pixel_set(sobol, 4, 4, 0));
}

TEST(CorePixelSampler, ArraysStratifyAndContinueThePixelsSequence) {
  // A progressive technique: each array an aligned block of the pixel's one
  // array set, so every array is a net and all spp arrays together one net.
  const auto sobol = shared_of(SobolOwenHash{}, 8);
  PixelSampler<SobolOwenHash> sampler(&sobol);
  Points all;
  for (std::uint32_t i = 0; i < 8; ++i) {
    sampler.start_pixel_sample(2, 7, i);
    sampler.get_pixel_2d();
    Points shadow(16);
    sampler.get_2d_array(16, shadow.data());
    EXPECT_TRUE(stratum::testing::is_zero_net(shadow)) << i;
    all.insert(all.end(), shadow.begin(), shadow.end());
  }
  EXPECT_TRUE(stratum::testing::is_zero_net(all));
  // They are points 0 … 127 of the set of the array seed.
  const SobolOwenHash technique;
  const auto key = technique.key({}, array_seed(7, 2, 7, 1, tag_continued));
  for (std::uint64_t i = 0; i < all.size(); ++i) EXPECT_EQ(all[i], technique.point<2>(key, {}, i));
  // A pattern draws a fresh stratified set per sample.
  const auto jittered = shared_of(JitteredTechnique{}, 4);
  PixelSampler<JitteredTechnique> pattern(&jittered);
  Points first(9), second(9);
  pattern.start_pixel_sample(0, 0, 0);
  pattern.get_2d_array(9, first.data());
  pattern.start_pixel_sample(0, 0, 1);
  pattern.get_2d_array(9, second.data());
  EXPECT_TRUE(one_per_cell(first, 3, 3));
  EXPECT_TRUE(one_per_cell(second, 3, 3));
  EXPECT_NE(first, second);
}

TEST(CorePixelSampler, FramesContinueAProgressivePixelsSequence) {
  // Frames 0 … 3 at 4 spp are the 16 samples of frame 0 at 16 spp: one net.
  const auto whole = shared_of(SobolOwenHash{}, 16);
  const Points sixteen = pixel_set(whole, 5, 5, 2);
  Points frames;
  for (std::uint32_t frame = 0; frame < 4; ++frame) {
    const Points part = pixel_set(shared_of(SobolOwenHash{}, 4, 7, frame), 5, 5, 2);
    frames.insert(frames.end(), part.begin(), part.end());
  }
  EXPECT_EQ(frames, sixteen);
  EXPECT_TRUE(stratum::testing::is_zero_net(frames));
  // A pattern's frames are independent sets, each stratified.
  const Points a = pixel_set(shared_of(JitteredTechnique{}, 9, 7, 0), 5, 5, 0);
  const Points b = pixel_set(shared_of(JitteredTechnique{}, 9, 7, 1), 5, 5, 0);
  EXPECT_TRUE(one_per_cell(b, 3, 3));
  EXPECT_NE(a, b);
  // (frame + 1) · spp past 2^32 is refused on the host.
  EXPECT_FALSE(Shared<SobolOwenHash>::make({}, 1u << 16, 7, 1u << 16).has_value());
  EXPECT_FALSE(Shared<JitteredTechnique>::make({}, 8, 7).has_value());  // not a square
}

/// Pearson's r of the pairs (a[i], b[i]).
double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const double n = double(a.size());
  double ma = 0, mb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) ma += a[i], mb += b[i];
  ma /= n, mb /= n;
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    sab += (a[i] - ma) * (b[i] - mb), saa += (a[i] - ma) * (a[i] - ma), sbb += (b[i] - mb) * (b[i] - mb);
  return sab / std::sqrt(saa * sbb);
}

/// Correlations of sample 3's first coordinate of dimension 0 with the
/// neighbouring pixel's (x + 1) and with dimension 1 of the same pixel, over
/// a 64 × 64 block: r·√N is about standard normal under independence.
/// (`shared_keys`: pixels 2k and 2k + 1 draw as one pixel, the fault the test must catch.)
template <class Technique>
std::array<double, 2> scaled_correlations(const Technique& technique, std::uint32_t spp, bool shared_keys = false) {
  const auto shared = shared_of(technique, spp, 11);
  PixelSampler<Technique> sampler(&shared);
  std::vector<double> here, right, other_dimension, here_all;
  std::vector<std::vector<double>> grid(64, std::vector<double>(65));
  for (std::uint32_t y = 0; y < 64; ++y)
    for (std::uint32_t x = 0; x < 65; ++x) {
      sampler.start_pixel_sample(shared_keys ? x / 2 : x, y, 3);
      grid[y][x] = sampler.get_2d()[0];
      if (x < 64) here_all.push_back(grid[y][x]), other_dimension.push_back(sampler.get_2d()[0]);
    }
  for (std::uint32_t y = 0; y < 64; ++y)
    for (std::uint32_t x = 0; x < 64; ++x) here.push_back(grid[y][x]), right.push_back(grid[y][x + 1]);
  const double root = std::sqrt(double(here.size()));
  return {correlation(here, right) * root, correlation(here_all, other_dimension) * root};
}

TEST(CorePixelSampler, PixelsAndDimensionsAreDecorrelated) {
  // 9 randomized techniques × 2 correlations, two-sided, family-wise
  // significance 0.001 with Šidák's correction: fixed seed, so a failure is
  // a property of the construction, not of chance at this level.
  constexpr int tests = 18;
  const double alpha = 1 - std::pow(1 - 0.001, 1.0 / tests);
  const double z = boost::math::quantile(boost::math::complement(boost::math::normal(), alpha / 2));
  const std::vector<std::pair<std::string, std::array<double, 2>>> measured = {
      {"random", scaled_correlations(RandomTechnique{}, 16)},
      {"jittered", scaled_correlations(JitteredTechnique{}, 16)},
      {"sobol:owen-hash", scaled_correlations(SobolOwenHash{}, 16)},
      {"sobol:owen", scaled_correlations(SobolTechnique<base2_scrambles::Owen>{}, 16)},
      {"sobol:lms", scaled_correlations(SobolTechnique<base2_scrambles::Lms>{}, 16)},
      {"pmj02", scaled_correlations(Pmj02Technique{}, 16)},
      {"halton:cp", scaled_correlations(HaltonTechnique{{}, true}, 16)},
      {"lattice-sequence:cp", scaled_correlations(LatticeSequenceTechnique{{}, true}, 16)},
      {"cmj", scaled_correlations(CmjTechnique{}, 16)},
  };
  ASSERT_EQ(int(measured.size()) * 2, tests);
  for (const auto& [name, r] : measured) {
    EXPECT_LT(std::abs(r[0]), z) << name << ": neighbouring pixels";
    EXPECT_LT(std::abs(r[1]), z) << name << ": dimensions 0 and 1";
  }
  // The test can fail: neighbouring pixels that share their sets half the time.
  EXPECT_GT(std::abs(scaled_correlations(SobolOwenHash{}, 16, true)[0]), z);
}

}  // namespace
