// ZSobol (sequences/zsobol.hpp): per-pixel (0,L,2)-nets, aligned quads of
// pixels that together form a larger net (the root of the blue-noise error),
// a bijective index map, unbiasedness over seeds (t-test, Šidák-corrected),
// and the registry's points equal to the renderer's draws.
#include "stratum/sequences/zsobol.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <set>
#include <vector>

#include "../patterns/unbiased.hpp"
#include "stratum/registry.hpp"
#ifdef STRATUM_HAS_RENDER
#include "stratum/render/pixel_sampler.hpp"
#endif
#include "zero_net.hpp"

namespace {

using stratum::ZSobol;
using stratum::testing::is_zero_net;

TEST(ZSobol, EachPixelIsANetInEveryPair) {
  for (std::uint64_t spp : {1u, 2u, 4u, 8u, 16u, 64u}) {
    const ZSobol z(16, spp, 7);
    for (std::uint32_t pair = 0; pair < 3; ++pair)
      for (auto [x, y] : {std::pair{0u, 0u}, std::pair{5u, 9u}, std::pair{15u, 15u}}) {
        std::vector<std::array<double, 2>> points;
        for (std::uint64_t i = 0; i < spp; ++i) points.push_back(z.sample_2d(x, y, i, pair));
        EXPECT_TRUE(is_zero_net(points)) << "spp " << spp << " pair " << pair << " pixel " << x << "," << y;
      }
  }
}

TEST(ZSobol, AnAlignedQuadOfPixelsIsOneLargerNet) {
  // Four pixels of a Morton quad share an aligned block of 4·spp indices:
  // their samples together stratify like one pixel of 4·spp samples.
  for (std::uint64_t spp : {1u, 4u, 8u}) {
    const ZSobol z(32, spp, 3);
    for (auto [qx, qy] : {std::pair{0u, 0u}, std::pair{6u, 10u}, std::pair{30u, 2u}}) {
      std::vector<std::array<double, 2>> points;
      for (std::uint32_t dy = 0; dy < 2; ++dy)
        for (std::uint32_t dx = 0; dx < 2; ++dx)
          for (std::uint64_t i = 0; i < spp; ++i) points.push_back(z.sample_2d(qx + dx, qy + dy, i, 1));
      EXPECT_TRUE(is_zero_net(points)) << "spp " << spp << " quad at " << qx << "," << qy;
    }
  }
  // and an unaligned pair of quads is not in general one net: the test can fail
  const ZSobol z(32, 1, 3);
  int nets = 0;
  for (std::uint32_t x = 1; x < 29; x += 4) {
    std::vector<std::array<double, 2>> points;
    for (std::uint32_t dy = 0; dy < 2; ++dy)
      for (std::uint32_t dx = 0; dx < 2; ++dx) points.push_back(z.sample_2d(x + dx, 1 + dy, 0, 1));
    nets += is_zero_net(points);
  }
  EXPECT_LT(nets, 7);
}

TEST(ZSobol, TheIndexMapIsABijection) {
  for (std::uint64_t spp : {1u, 2u, 8u}) {
    const ZSobol z(8, spp, 11);
    const auto pair = z.pair(2);
    std::set<std::uint64_t> seen;
    for (std::uint32_t y = 0; y < 8; ++y)
      for (std::uint32_t x = 0; x < 8; ++x)
        for (std::uint64_t i = 0; i < spp; ++i) {
          const std::uint64_t s = z.sequence_index(x, y, i, pair);
          EXPECT_LT(s, 64 * spp);
          seen.insert(s);
        }
    EXPECT_EQ(seen.size(), 64 * spp);
  }
}

TEST(ZSobol, TheSampleDigitTableIsEachSamplesDigits) {
  // Odd and even index widths (the lone base-2 digit), frames past the
  // image's digits, spp from 1 to 256.
  for (std::uint32_t resolution : {1u, 6u, 16u, 100u})
    for (std::uint64_t spp : {1u, 2u, 4u, 8u, 16u, 32u, 256u}) {
      const ZSobol z(resolution, spp, 5);
      for (std::uint32_t p : {0u, 3u}) {
        const auto pair = z.pair(p);
        std::vector<std::uint64_t> table(spp);
        for (auto [x, y] : {std::pair{0u, 0u}, {resolution - 1, resolution / 2}})
          for (std::uint64_t frame : {0ull, 1ull, 77777ull}) {
            z.sample_digit_table(x, y, pair, frame, table.data());
            for (std::uint64_t i = 0; i < spp; ++i)
              ASSERT_EQ(table[i], z.sample_digits(x, y, 0, i, pair, frame))
                  << "resolution " << resolution << " spp " << spp << " pixel " << x << "," << y << " frame " << frame
                  << " sample " << i;
          }
      }
    }
}

TEST(ZSobol, BlockDigitsComposeToThePixelDigits) {
  for (std::uint32_t resolution : {1u, 5u, 16u, 100u, 4096u})
    for (std::uint64_t spp : {1u, 2u, 32u}) {
      const ZSobol z(resolution, spp, 5);
      for (unsigned k : {0u, 1u, 4u, 9u})
        for (std::uint32_t p = 0; p < 3; ++p) {
          const auto pair = z.pair(p);
          for (auto [x, y] :
               {std::pair{0u, 0u}, std::pair{resolution - 1, resolution / 2}, std::pair{resolution / 3, 0u}}) {
            const std::uint64_t block = z.block_digits(x, y, pair, k);
            EXPECT_EQ(z.pixel_digits(x, y, pair, block, k), z.pixel_digits(x, y, pair))
                << "resolution " << resolution << " spp " << spp << " k " << k;
          }
        }
    }
}

TEST(ZSobol, UnbiasedOverSeeds) {
  // 3 pixels × 2 spp values = 6 t-tests at family level 0.01.
  const double alpha = stratum::testing::sidak(0.01, 6);
  for (std::uint64_t spp : {1u, 16u})
    for (auto [x, y] : {std::pair{0u, 0u}, std::pair{3u, 1u}, std::pair{7u, 6u}}) {
      std::vector<double> estimates;
      for (std::uint64_t seed = 0; seed < 400; ++seed) {
        const ZSobol z(8, spp, seed);
        double sum = 0;
        for (std::uint64_t i = 0; i < spp; ++i) {
          const auto a = z.sample_2d(x, y, i, 0), b = z.sample_2d(x, y, i, 1);
          sum += a[0] * a[1] * a[1] * std::exp(b[0]);
        }
        estimates.push_back(sum / double(spp));
      }
      stratum::testing::expect_unbiased("zsobol spp " + std::to_string(spp), estimates,
                                        stratum::testing::product_test_integral(), alpha);
    }
}

TEST(ZSobol, RefusesWhatItCannotTake) {
  EXPECT_THROW(ZSobol(16, 3, 0), stratum::invalid_argument);
  EXPECT_THROW(ZSobol(0, 4, 0), stratum::invalid_argument);
  EXPECT_THROW(ZSobol(20000, 4, 0), stratum::invalid_argument);
  stratum::SamplerRequest request;
  request.n = 4;
  request.params = {{"pixel", "8,0"}, {"resolution", "8"}};
  EXPECT_THROW(stratum::generate_points("zsobol", request), stratum::invalid_argument);
}

#ifdef STRATUM_HAS_RENDER
TEST(ZSobol, RegistryPointsAreTheRenderersDraws) {
  stratum::render::PixelSamplerSettings settings;
  settings.sampler = "zsobol";
  settings.spp = 8;
  settings.seed = 21;
  settings.resolution = 40;
  // frame K's draws are the registry's points from start = K · spp on
  for (std::uint32_t frame : {0u, 3u, 70u}) {
    settings.frame = frame;
    stratum::render::PixelSampler sampler(settings);
    for (auto [x, y] : {std::pair{0u, 0u}, std::pair{17u, 33u}, std::pair{39u, 2u}}) {
      stratum::SamplerRequest request;
      request.n = 8;
      request.d = 6;
      request.seed = 21;
      request.start = std::uint64_t{frame} * 8;
      request.params = {{"pixel", std::to_string(x) + "," + std::to_string(y)}, {"resolution", "40"}};
      const stratum::PointSet points = stratum::generate_points("zsobol", request);
      for (std::uint32_t i = 0; i < 8; ++i) {
        sampler.start_pixel_sample(x, y, i);
        const auto film = sampler.get_pixel_2d();
        const double time = sampler.get_time();
        const auto lens = sampler.get_2d();
        EXPECT_EQ(film[0], points(i, 0));
        EXPECT_EQ(film[1], points(i, 1));
        EXPECT_EQ(time, points(i, 2));
        EXPECT_EQ(lens[0], points(i, 4));
        EXPECT_EQ(lens[1], points(i, 5));
      }
    }
  }
}
#endif

}  // namespace
