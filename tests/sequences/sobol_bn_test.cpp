// sobol-bn (sequences/sobol_bn.hpp): per-pixel (0,m,2)-nets in every pair
// (table and padding), unbiasedness over seeds (t-tests, Šidák-corrected),
// the key file round trip and its refusals, the committed default tile, and
// the registry's points equal to the renderer's draws.
#include "stratum/sequences/sobol_bn.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <vector>

#include "../patterns/unbiased.hpp"
#include "stratum/registry.hpp"
#ifdef STRATUM_HAS_RENDER
#include "stratum/render/pixel_sampler.hpp"
#endif

namespace {

using stratum::SobolBn;

bool is_zero_net(const std::vector<std::array<double, 2>>& points) {
  const std::size_t n = points.size();
  const int m = std::countr_zero(n);
  for (int a = 0; a <= m; ++a) {
    std::vector<int> count(n, 0);
    for (const auto& p : points) {
      const auto i = static_cast<std::size_t>(p[0] * double(1u << a)), j = static_cast<std::size_t>(p[1] * double(1u << (m - a)));
      ++count[i * (std::size_t(1) << (m - a)) + j];
    }
    for (int c : count)
      if (c != 1) return false;
  }
  return true;
}

TEST(SobolBn, EachPixelIsANetInEveryPair) {
  const SobolBn z(stratum::default_blue_noise_keys(), 7);
  const std::uint32_t pairs = z.table_pairs() + 2;  // two padding pairs too
  for (std::uint64_t spp : {1u, 2u, 4u, 8u, 16u, 64u, 256u})
    for (std::uint32_t pair = 0; pair < pairs; ++pair)
      for (auto [x, y] : {std::pair{0u, 0u}, std::pair{5u, 9u}, std::pair{63u, 200u}, std::pair{1000u, 3u}}) {
        std::vector<std::array<double, 2>> points;
        for (std::uint64_t i = 0; i < spp; ++i) points.push_back(z.sample_2d(x, y, i, pair));
        EXPECT_TRUE(is_zero_net(points)) << "spp " << spp << " pair " << pair << " pixel " << x << "," << y;
      }
}

TEST(SobolBn, NeighboursDifferAndTheTileWraps) {
  const stratum::BlueNoiseKeys& table = stratum::default_blue_noise_keys();
  const SobolBn z(table, 3);
  const std::uint32_t s = table.size;
  for (std::uint32_t pair = 0; pair < z.table_pairs(); ++pair) {
    // a pixel and the pixel one tile away take the same keys: the same points
    EXPECT_EQ(z.sample_2d(4, 9, 3, pair), z.sample_2d(4 + s, 9 + 2 * s, 3, pair));
    // and its neighbour other ones (the check can fail: keys could repeat)
    EXPECT_NE(z.sample_2d(4, 9, 0, pair), z.sample_2d(5, 9, 0, pair));
  }
  // padding pairs do not wrap: per-pixel scrambles
  EXPECT_NE(z.sample_2d(4, 9, 0, z.table_pairs()), z.sample_2d(4 + s, 9, 0, z.table_pairs()));
}

TEST(SobolBn, UnbiasedOverSeeds) {
  // 3 pixels × 2 spp values × 2 (table, padding) = 12 t-tests at family level 0.01.
  const double alpha = stratum::testing::sidak(0.01, 12);
  const stratum::BlueNoiseKeys& table = stratum::default_blue_noise_keys();
  const std::uint32_t padding = table.dims / 2;
  for (std::uint32_t first : {0u, padding})
    for (std::uint64_t spp : {1u, 16u})
      for (auto [x, y] : {std::pair{0u, 0u}, std::pair{3u, 1u}, std::pair{77u, 6u}}) {
        std::vector<double> estimates;
        for (std::uint64_t seed = 0; seed < 400; ++seed) {
          const SobolBn z(table, seed);
          double sum = 0;
          for (std::uint64_t i = 0; i < spp; ++i) {
            const auto a = z.sample_2d(x, y, i, first), b = z.sample_2d(x, y, i, first + 1);
            sum += a[0] * a[1] * a[1] * std::exp(b[0]);
          }
          estimates.push_back(sum / double(spp));
        }
        stratum::testing::expect_unbiased("sobol-bn pair " + std::to_string(first) + " spp " + std::to_string(spp),
                                          estimates, stratum::testing::product_test_integral(), alpha);
      }
}

TEST(SobolBn, TheKeyFileRoundTripsAndBadFilesAreRefused) {
  stratum::BlueNoiseKeys table{16, 2, 4, 3, 5, 99, std::vector<std::uint16_t>(16 * 16 * 2)};
  for (std::size_t i = 0; i < table.keys.size(); ++i) table.keys[i] = static_cast<std::uint16_t>(i * 2654435761u >> 7);
  const std::string bytes = stratum::serialize_blue_noise_keys(table);
  EXPECT_EQ(bytes.size(), 36u + 2 * table.keys.size());
  EXPECT_EQ(stratum::parse_blue_noise_keys(bytes, "t"), table);
  EXPECT_THROW(stratum::parse_blue_noise_keys(bytes.substr(0, bytes.size() - 1), "t"), stratum::invalid_argument);
  EXPECT_THROW(stratum::parse_blue_noise_keys("STRBNK02" + bytes.substr(8), "t"), stratum::invalid_argument);
  std::string odd = bytes;
  odd[12] = 3;  // dims 3
  EXPECT_THROW(stratum::parse_blue_noise_keys(odd, "t"), stratum::invalid_argument);
  stratum::SamplerRequest request;
  request.n = 4;
  request.params = {{"table", "/nonexistent/keys.bin"}};
  EXPECT_THROW(stratum::generate_points("sobol-bn", request), stratum::invalid_argument);
}

TEST(SobolBn, TheDefaultTileIsTheDocumentedOne) {
  // docs/blue-noise.md: stratum optimize blue-noise --size 128 --dims 8 --seed 1 (defaults otherwise)
  const stratum::BlueNoiseKeys& table = stratum::default_blue_noise_keys();
  EXPECT_EQ(table.size, 128u);
  EXPECT_EQ(table.dims, 8u);
  EXPECT_EQ(table.seed, 1u);
  EXPECT_EQ(table.max_spp, 16u);
  EXPECT_EQ(table.keys.size(), 128u * 128u * 8u);
}

#ifdef STRATUM_HAS_RENDER
TEST(SobolBn, RegistryPointsAreTheRenderersDraws) {
  stratum::render::PixelSamplerSettings settings;
  settings.sampler = "sobol-bn";
  settings.spp = 8;
  settings.seed = 21;
  stratum::render::PixelSampler sampler(settings);
  const std::uint32_t d = 2 * (stratum::default_blue_noise_keys().dims / 2 + 1);  // one padding pair too
  for (auto [x, y] : {std::pair{0u, 0u}, std::pair{17u, 33u}, std::pair{390u, 2u}}) {
    stratum::SamplerRequest request;
    request.n = 8;
    request.d = d;
    request.seed = 21;
    request.params = {{"pixel", std::to_string(x) + "," + std::to_string(y)}};
    const stratum::PointSet points = stratum::generate_points("sobol-bn", request);
    for (std::uint32_t i = 0; i < 8; ++i) {
      sampler.start_pixel_sample(x, y, i);
      const auto film = sampler.get_pixel_2d();
      const double time = sampler.get_time();
      EXPECT_EQ(film[0], points(i, 0));
      EXPECT_EQ(film[1], points(i, 1));
      EXPECT_EQ(time, points(i, 2));
      for (std::uint32_t p = 2; p < d / 2; ++p) {
        const auto u = sampler.get_2d();
        EXPECT_EQ(u[0], points(i, 2 * p));
        EXPECT_EQ(u[1], points(i, 2 * p + 1));
      }
    }
  }
  // a one-point array of sample i is the pair's point i; a 4-point array is points 4i..4i+3
  sampler.start_pixel_sample(5, 6, 3);
  std::array<double, 2> one[1], four[4];
  sampler.get_2d_array(1, one);
  sampler.get_2d_array(4, four);
  const SobolBn z(stratum::default_blue_noise_keys(), 21);
  EXPECT_EQ(one[0], z.sample_2d(5, 6, 3, 0));
  for (std::uint32_t j = 0; j < 4; ++j) EXPECT_EQ(four[j], z.sample_2d(5, 6, 12 + j, 1));
}
#endif

}  // namespace
