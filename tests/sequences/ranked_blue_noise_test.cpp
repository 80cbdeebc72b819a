// sobol-bn, pmj02-bn, lattice-bn (sequences/ranked_blue_noise.hpp): per-pixel
// (0,m,2)-nets (sobol, pmj02) or one shifted rank-1 lattice (lattice) in every
// pair (table and padding), the tile's pixels partitioning the sequence,
// unbiasedness over seeds (t-tests, Šidák-corrected), the key file round trip
// and its refusals, the committed default tiles, and the registry's points
// equal to the renderer's draws.
#include "stratum/sequences/ranked_blue_noise.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "../patterns/unbiased.hpp"
#include "stratum/registry.hpp"
#ifdef STRATUM_HAS_RENDER
#include "stratum/render/pixel_sampler.hpp"
#endif
#include "zero_net.hpp"

namespace {

using stratum::BlueNoiseBase;
using stratum::RankedBlueNoise;
using stratum::testing::is_zero_net;

constexpr BlueNoiseBase bases[] = {BlueNoiseBase::sobol, BlueNoiseBase::pmj02, BlueNoiseBase::lattice};
std::string name_of(BlueNoiseBase base) { return std::string(stratum::blue_noise_base_name(base)) + "-bn"; }

TEST(RankedBlueNoise, EachPixelIsANetInEveryPair) {
  for (BlueNoiseBase base : {BlueNoiseBase::sobol, BlueNoiseBase::pmj02})
    for (std::uint64_t spp : {1u, 2u, 4u, 8u, 16u, 64u, 256u}) {
      const RankedBlueNoise z(stratum::default_blue_noise_table(base), spp, 7);
      const std::uint32_t pairs = z.table_pairs() + 2;  // two padding pairs too
      for (std::uint32_t pair = 0; pair < pairs; ++pair)
        for (auto [x, y] : {std::pair{0u, 0u}, std::pair{5u, 9u}, std::pair{63u, 200u}, std::pair{1000u, 3u}}) {
          std::vector<std::array<double, 2>> points;
          for (std::uint64_t i = 0; i < spp; ++i) points.push_back(z.sample_2d(x, y, i, pair));
          EXPECT_TRUE(is_zero_net(points))
              << name_of(base) << " spp " << spp << " pair " << pair << " pixel " << x << "," << y;
        }
    }
}

/// The lattice index k of each sample in coordinate c (g_c odd): x_i − x_0 ≡
/// k_i g_c / spp (mod 1), so k_i = (x_i − x_0)·spp · g_c⁻¹ mod spp; −1 where
/// x_i − x_0 is not a multiple of 1/spp.
std::vector<std::int64_t> lattice_indices(const std::vector<double>& x, std::uint64_t g) {
  const std::uint64_t spp = x.size();
  std::uint64_t inverse = 1;  // g⁻¹ mod 2^64 by Newton's iteration, then mod spp
  for (int i = 0; i < 6; ++i) inverse *= 2 - g * inverse;
  std::vector<std::int64_t> k;
  for (double xi : x) {
    double d = (xi - x[0]) * double(spp);
    d -= std::floor(d / double(spp)) * double(spp);
    const double r = std::round(d);
    if (std::abs(d - r) > 1e-6) return std::vector<std::int64_t>(spp, -1);
    k.push_back(std::int64_t((std::uint64_t(r) % spp * inverse) & (spp - 1)));
  }
  return k;
}

TEST(RankedBlueNoise, EachLatticePixelIsOneShiftedRankOneLattice) {
  // Every coordinate of a pixel (table and padding pairs, past the 16 pairs
  // of the generating vector too) is the 2^m-point lattice frac(k g_c / 2^m)
  // shifted, and all coordinates of sample i share one k (a lattice in all
  // dimensions jointly) within the generator's 32 coordinates; each k once.
  const auto& g = stratum::LatticeSequence::default_generator;
  for (std::uint64_t spp : {2u, 4u, 16u, 64u}) {
    const RankedBlueNoise z(stratum::default_blue_noise_table(BlueNoiseBase::lattice), spp, 11);
    for (auto [x, y] : {std::pair{0u, 0u}, std::pair{5u, 9u}, std::pair{1000u, 3u}}) {
      std::vector<std::int64_t> first;
      for (std::uint32_t pair = 0; pair < 18; ++pair)
        for (unsigned c = 0; c < 2; ++c) {
          std::vector<double> coordinate;
          for (std::uint64_t i = 0; i < spp; ++i) coordinate.push_back(z.sample_2d(x, y, i, pair)[c]);
          std::vector<std::int64_t> k = lattice_indices(coordinate, g[(2 * pair + c) % g.size()]);
          std::vector<std::int64_t> sorted = k;
          std::sort(sorted.begin(), sorted.end());
          for (std::uint64_t i = 0; i < spp; ++i)
            ASSERT_EQ(sorted[i], std::int64_t(i)) << "spp " << spp << " pair " << pair << " pixel " << x << "," << y;
          if (first.empty()) first = k;
          if (2 * pair + c < g.size()) {
            EXPECT_EQ(k, first) << "spp " << spp << " pair " << pair << " coordinate " << c;
          } else if (spp >= 4) {  // a reused component pairs its samples otherwise than its first use (2 points:
                                  // any pairing is a shift of the other)
            EXPECT_NE(k, first) << "spp " << spp << " pair " << pair << " coordinate " << c;
          }
        }
    }
  }
}

TEST(RankedBlueNoise, TheTilesPixelsPartitionTheSequence) {
  // Any size × size window of pixels takes each rank once (the tile wraps),
  // so neighbouring pixels never share a block.
  for (BlueNoiseBase base : bases)
    for (std::uint64_t spp : {1u, 4u}) {
      const stratum::BlueNoiseTable& table = stratum::default_blue_noise_table(base);
      const RankedBlueNoise z(table, spp, 0);
      for (std::uint32_t pair = 0; pair < z.table_pairs(); ++pair) {
        std::vector<bool> seen(std::size_t{table.size} * table.size, false);
        for (std::uint32_t y = 0; y < table.size; ++y)
          for (std::uint32_t x = 0; x < table.size; ++x) {
            const auto p = z.pixel_pair(x, y, pair);
            ASSERT_EQ(p.first % spp, 0u);
            const std::uint64_t block = p.first / spp;
            const std::uint64_t rank = block % seen.size();
            EXPECT_FALSE(seen[rank]);
            seen[rank] = true;
          }
        EXPECT_EQ(std::count(seen.begin(), seen.end(), true), std::ptrdiff_t(seen.size()));
      }
    }
}

TEST(RankedBlueNoise, TheTileWrapsOverFreshBlocks) {
  const stratum::BlueNoiseTable& table = stratum::default_blue_noise_table();
  const RankedBlueNoise z(table, 4, 3);
  const std::uint32_t s = table.size;
  for (std::uint32_t pair = 0; pair < z.table_pairs(); ++pair) {
    // a pixel and the pixel one tile away take the same rank in the next tile's blocks
    const std::uint64_t pixels = std::uint64_t{s} * s;
    EXPECT_EQ(z.pixel_pair(4, 9, pair).first / 4 % pixels, z.pixel_pair(4 + s, 9 + 2 * s, pair).first / 4 % pixels);
    EXPECT_NE(z.pixel_pair(4, 9, pair).first, z.pixel_pair(4 + s, 9 + 2 * s, pair).first);
    EXPECT_NE(z.sample_2d(4, 9, 0, pair), z.sample_2d(5, 9, 0, pair));
  }
  // padding pairs do not wrap: per-pixel scrambles
  EXPECT_NE(z.sample_2d(4, 9, 0, z.table_pairs()), z.sample_2d(4 + s, 9, 0, z.table_pairs()));
}

TEST(RankedBlueNoise, UnbiasedOverSeeds) {
  // 3 bases × 3 pixels × 2 spp values × 2 (table, padding) = 36 t-tests at family level 0.01.
  const double alpha = stratum::testing::sidak(0.01, 36);
  for (BlueNoiseBase base : bases) {
    const stratum::BlueNoiseTable& table = stratum::default_blue_noise_table(base);
    const std::uint32_t padding = table.dims / 2;
    for (std::uint32_t first : {0u, padding})
      for (std::uint64_t spp : {1u, 16u})
        for (auto [x, y] : {std::pair{0u, 0u}, std::pair{3u, 1u}, std::pair{77u, 6u}}) {
          std::vector<double> estimates;
          for (std::uint64_t seed = 0; seed < 400; ++seed) {
            const RankedBlueNoise z(table, spp, seed);
            double sum = 0;
            for (std::uint64_t i = 0; i < spp; ++i) {
              const auto a = z.sample_2d(x, y, i, first), b = z.sample_2d(x, y, i, first + 1);
              sum += a[0] * a[1] * a[1] * std::exp(b[0]);
            }
            estimates.push_back(sum / double(spp));
          }
          stratum::testing::expect_unbiased(
              name_of(base) + " pair " + std::to_string(first) + " spp " + std::to_string(spp), estimates,
              stratum::testing::product_test_integral(), alpha);
        }
  }
}

TEST(RankedBlueNoise, TheKeyFileRoundTripsAndBadFilesAreRefused) {
  stratum::BlueNoiseTable table{BlueNoiseBase::pmj02,
                                stratum::BlueNoiseStructure::morton,
                                16,
                                4,
                                4,
                                3,
                                5,
                                99,
                                std::vector<std::uint16_t>(16 * 16 * 2)};
  for (std::size_t i = 0; i < 256; ++i)
    table.ranks[2 * i] = std::uint16_t(i), table.ranks[2 * i + 1] = std::uint16_t(255 - i);
  const std::string bytes = stratum::serialize_blue_noise_table(table);
  EXPECT_EQ(bytes.substr(0, 8), "STRBNR02");
  EXPECT_EQ(bytes.size(), 44u + 2 * table.ranks.size());
  EXPECT_EQ(stratum::parse_blue_noise_table(bytes, "t"), table);
  // a version-1 file (no base and structure fields) is a free sobol tile
  stratum::BlueNoiseTable v1 = table;
  v1.base = BlueNoiseBase::sobol;
  v1.structure = stratum::BlueNoiseStructure::free;
  EXPECT_EQ(stratum::parse_blue_noise_table("STRBNR01" + bytes.substr(16), "t"), v1);
  EXPECT_THROW(stratum::parse_blue_noise_table(bytes.substr(0, bytes.size() - 1), "t"), stratum::invalid_argument);
  EXPECT_THROW(stratum::parse_blue_noise_table("STRBNR03" + bytes.substr(8), "t"), stratum::invalid_argument);
  std::string base = bytes;
  base[8] = 3;  // no such base
  EXPECT_THROW(stratum::parse_blue_noise_table(base, "t"), stratum::invalid_argument);
  std::string structure = bytes;
  structure[12] = 2;  // no such structure
  EXPECT_THROW(stratum::parse_blue_noise_table(structure, "t"), stratum::invalid_argument);
  std::string odd = bytes;
  odd[20] = 3;  // dims 3
  EXPECT_THROW(stratum::parse_blue_noise_table(odd, "t"), stratum::invalid_argument);
  std::string repeated = bytes;
  repeated[44] = 1;  // pixel 0's rank of pair 0 = pixel 1's: not a permutation
  EXPECT_THROW(stratum::parse_blue_noise_table(repeated, "t"), stratum::invalid_argument);
  std::string not_power = bytes;
  not_power[16] = 24;
  EXPECT_THROW(stratum::parse_blue_noise_table(not_power, "t"), stratum::invalid_argument);
  // a lattice tile covers at most the 32 components of its generating vector
  stratum::BlueNoiseTable wide{BlueNoiseBase::lattice,
                               stratum::BlueNoiseStructure::free,
                               16,
                               34,
                               4,
                               3,
                               5,
                               99,
                               std::vector<std::uint16_t>(16 * 16 * 17)};
  for (std::size_t i = 0; i < wide.ranks.size(); ++i) wide.ranks[i] = std::uint16_t(i / 17);
  EXPECT_THROW(stratum::parse_blue_noise_table(stratum::serialize_blue_noise_table(wide), "t"),
               stratum::invalid_argument);
  wide.base = BlueNoiseBase::pmj02;
  EXPECT_NO_THROW(stratum::parse_blue_noise_table(stratum::serialize_blue_noise_table(wide), "t"));

  stratum::SamplerRequest request;
  request.n = 4;
  request.params = {{"table", "/nonexistent/keys.bin"}};
  EXPECT_THROW(stratum::generate_points("sobol-bn", request), stratum::invalid_argument);
  // a tile of one base is refused by another base's sampler, accepted by its own
  const std::string path = (std::filesystem::temp_directory_path() / "stratum-ranked-pmj02.bin").string();
  std::ofstream(path, std::ios::binary) << bytes;
  request.params = {{"table", path}};
  EXPECT_THROW(stratum::generate_points("sobol-bn", request), stratum::invalid_argument);
  EXPECT_THROW(stratum::generate_points("lattice-bn", request), stratum::invalid_argument);
  EXPECT_EQ(stratum::generate_points("pmj02-bn", request).n, 4u);
  std::remove(path.c_str());
}

TEST(RankedBlueNoise, TheDefaultTilesAreTheDocumentedOnes) {
  // docs/blue-noise.md: stratum optimize blue-noise --base B --size 128 --dims 8 --seed 1 (defaults otherwise;
  // the lattice --structure free)
  for (BlueNoiseBase base : bases) {
    const stratum::BlueNoiseTable& table = stratum::default_blue_noise_table(base);
    EXPECT_EQ(table.base, base);
    // morton for sobol and pmj02; free for the lattice (its Morton tile was worse than white in pair 2)
    EXPECT_EQ(table.structure,
              base == BlueNoiseBase::lattice ? stratum::BlueNoiseStructure::free : stratum::BlueNoiseStructure::morton);
    EXPECT_EQ(table.size, 128u);
    EXPECT_EQ(table.dims, 8u);
    EXPECT_EQ(table.seed, 1u);
    EXPECT_EQ(table.max_spp, 16u);
    EXPECT_EQ(table.ranks.size(), 128u * 128u * 4u);
  }
}

#ifdef STRATUM_HAS_RENDER
TEST(RankedBlueNoise, RegistryPointsAreTheRenderersDraws) {
  for (BlueNoiseBase base : bases) {
    const std::string name = name_of(base);
    const stratum::BlueNoiseTable& table = stratum::default_blue_noise_table(base);
    stratum::render::PixelSamplerSettings settings;
    settings.sampler = name;
    settings.spp = 8;
    settings.seed = 21;
    const std::uint32_t d = 2 * (table.dims / 2 + 1);  // one padding pair too
    // frame K's draws are the registry's points from start = K · spp on
    for (std::uint32_t frame : {3u, 70u}) {
      settings.frame = frame;
      stratum::render::PixelSampler framed(settings);
      stratum::SamplerRequest request;
      request.n = 8;
      request.d = d;
      request.seed = 21;
      request.start = std::uint64_t{frame} * 8;
      request.params = {{"pixel", "17,33"}};
      const stratum::PointSet points = stratum::generate_points(name, request);
      for (std::uint32_t i = 0; i < 8; ++i) {
        framed.start_pixel_sample(17, 33, i);
        const auto film = framed.get_pixel_2d();
        EXPECT_EQ(film[0], points(i, 0)) << name << " frame " << frame;
        EXPECT_EQ(film[1], points(i, 1)) << name << " frame " << frame;
        EXPECT_EQ(framed.get_time(), points(i, 2)) << name << " frame " << frame;
        for (std::uint32_t p = 2; p < d / 2; ++p) {
          const auto u = framed.get_2d();
          EXPECT_EQ(u[0], points(i, 2 * p)) << name << " frame " << frame;
          EXPECT_EQ(u[1], points(i, 2 * p + 1)) << name << " frame " << frame;
        }
      }
    }
    settings.frame = 0;
    stratum::render::PixelSampler sampler(settings);
    for (auto [x, y] : {std::pair{0u, 0u}, std::pair{17u, 33u}, std::pair{390u, 2u}}) {
      stratum::SamplerRequest request;
      request.n = 8;
      request.d = d;
      request.seed = 21;
      request.params = {{"pixel", std::to_string(x) + "," + std::to_string(y)}};
      const stratum::PointSet points = stratum::generate_points(name, request);
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
    // a one-point array of sample i is the pair's sample i; the 8 four-point arrays of the pixel's samples are
    // together its 32-point block of the pair (a net for sobol and pmj02)
    sampler.start_pixel_sample(5, 6, 3);
    std::array<double, 2> one[1];
    sampler.get_2d_array(1, one);
    const RankedBlueNoise z(table, 8, 21);
    EXPECT_EQ(one[0], z.sample_2d(5, 6, 3, 0));
    const RankedBlueNoise z32(table, 32, 21);
    std::vector<std::array<double, 2>> arrays, block;
    for (std::uint32_t i = 0; i < 8; ++i) {
      sampler.start_pixel_sample(5, 6, i);
      sampler.get_pixel_2d();  // pair 0; the array is pair 1
      std::array<double, 2> four[4];
      sampler.get_2d_array(4, four);
      for (std::uint32_t j = 0; j < 4; ++j) {
        EXPECT_EQ(four[j], z.array_point(i, 4, j, z.pixel_pair(5, 6, 1)));
        arrays.push_back(four[j]);
      }
    }
    for (std::uint32_t i = 0; i < 32; ++i)
      block.push_back(z32.point_at(z32.pixel_pair(5, 6, 1).first + i, z32.pixel_pair(5, 6, 1)));
    std::sort(arrays.begin(), arrays.end());
    std::sort(block.begin(), block.end());
    EXPECT_EQ(arrays, block) << name;
  }
}

TEST(RankedBlueNoise, EachPixelAndPairReadsItsBlockInItsOwnOrder) {
  // sobol-bn and pmj02-bn: at spp = 2^m the pixel's pair p reads its block at
  // sample index i XOR c(x, y, p), so the pairing of samples across pairs
  // differs between pixels and pairs (a pairing shared by the image made the
  // error white at 16 spp); every 2^k prefix of a pixel's samples is still an
  // aligned sub-block, a (0,k,2)-net. The lattice keeps its order (its pairs
  // are one lattice jointly; EachLatticePixelIsOneShiftedRankOneLattice).
  for (BlueNoiseBase base : {BlueNoiseBase::sobol, BlueNoiseBase::pmj02}) {
    const RankedBlueNoise z(stratum::default_blue_noise_table(base), 16, 3);
    std::vector<std::uint64_t> orders;
    for (std::uint32_t x = 0; x < 8; ++x)
      for (std::uint32_t pair = 0; pair < 4; ++pair) {
        orders.push_back(z.pixel_pair(x, 0, pair).index_xor);
        for (std::uint64_t k : {1u, 2u, 4u, 8u}) {
          std::vector<std::array<double, 2>> prefix;
          for (std::uint64_t i = 0; i < k; ++i) prefix.push_back(z.sample_2d(x, 0, i, pair));
          EXPECT_TRUE(is_zero_net(prefix)) << name_of(base) << " prefix " << k;
        }
      }
    std::sort(orders.begin(), orders.end());
    EXPECT_GE(std::unique(orders.begin(), orders.end()) - orders.begin(), 8) << name_of(base);
  }
  const RankedBlueNoise lattice(stratum::default_blue_noise_table(BlueNoiseBase::lattice), 16, 3);
  EXPECT_EQ(lattice.pixel_pair(3, 1, 2).index_xor, 0u);
  // spp not a power of 2: no XOR (it could leave the block)
  const RankedBlueNoise twelve(stratum::default_blue_noise_table(), 12, 3);
  EXPECT_EQ(twelve.pixel_pair(3, 1, 2).index_xor, 0u);
}
#endif

}  // namespace
