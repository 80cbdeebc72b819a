// The registry entries of the finite patterns (src/registry/samplers_patterns.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "../patterns/unbiased.hpp"
#include "bulk_permutation.hpp"
#include "error_of.hpp"
#include "stratum/patterns/latin_hypercube.hpp"
#include "stratum/patterns/strata.hpp"
#include "stratum/registry.hpp"
#include "stratum/util/error.hpp"

namespace stratum {
namespace {

using testing::error_of;

SamplerRequest request_of(std::uint64_t n, unsigned d, std::uint64_t seed = 1) {
  SamplerRequest request;
  request.n = n;
  request.d = d;
  request.seed = seed;
  return request;
}

TEST(PatternRegistry, EntriesExistWithTheRightKind) {
  for (const char* name : {"random", "grid", "jittered", "n-rooks", "latin-hypercube", "multi-jittered", "cmj",
                           "n-queens", "latin-square", "zaremba"}) {
    const SamplerInfo& info = find_sampler(name);
    EXPECT_EQ(info.kind, "pattern") << name;
  }
  EXPECT_NE(find_sampler("latin-hypercube").description.find("alias"), std::string::npos);
}

TEST(PatternRegistry, LatinHypercubeIsAnAliasOfNRooks) {
  for (bool centered : {false, true}) {
    auto request = request_of(1000, 4, 17);
    if (centered) request.params["centered"] = "1";
    const PointSet a = generate_points("n-rooks", request), b = generate_points("latin-hypercube", request);
    ASSERT_EQ(a.n * a.d, b.n * b.d);
    EXPECT_EQ(0, std::memcmp(a.data.get(), b.data.get(), a.n * a.d * sizeof(double)));
  }
}

// The registry's blocked, row-major fill equals LatinHypercube::generate
// (one dimension at a time) bit for bit: d around the block of 8, centered
// or not, one thread or two.
TEST(PatternRegistry, NRooksEqualsLatinHypercubeGenerate) {
  for (unsigned d : {1u, 3u, 8u, 9u, 17u})
    for (std::uint64_t n : {1u, 5u, 1000u})
      for (bool centered : {false, true})
        for (unsigned threads : {1u, 2u}) {
          SamplerRequest request = request_of(n, d, 11);
          request.threads = threads;
          if (centered) request.params["centered"] = "1";
          const PointSet points = generate_points("n-rooks", request);
          const LatinHypercube lhs(n, d, 11, centered);
          std::vector<double> expected(n * d);
          std::vector<std::uint64_t> scratch(n);
          lhs.generate(expected.data(), scratch.data());
          for (std::uint64_t i = 0; i < n; ++i)
            for (unsigned j = 0; j < d; ++j)
              ASSERT_EQ(points(i, j), expected[i * d + j]) << "d " << d << " n " << n << " i " << i << " j " << j;
        }
}

// The bulk Fisher-Yates (vectorized draws) is random_permutation exactly:
// n below, at and past its chunk of 2048 steps, several keys.
TEST(PatternRegistry, BulkPermutationEqualsRandomPermutation) {
  for (std::uint64_t n : {1u, 2u, 3u, 100u, 2048u, 2049u, 4097u, 70000u})
    for (std::uint64_t key : {0ull, 1ull, 0x9e3779b97f4a7c15ull, ~0ull}) {
      std::vector<std::uint32_t> bulk(n), reference(n);
      registry_support::bulk_random_permutation(bulk.data(), n, key);
      random_permutation(reference.data(), n, key);
      ASSERT_EQ(bulk, reference) << "n " << n << " key " << key;
    }
}

TEST(PatternRegistry, GridTakesStrataAndValidatesN) {
  auto request = request_of(32, 2);
  request.params["strata"] = "4x8";
  const PointSet grid = generate_points("grid", request);
  EXPECT_EQ(grid(0, 0), 0.125);
  EXPECT_EQ(grid(0, 1), 1.0 / 16);
  EXPECT_EQ(grid(31, 0), 0.875);
  EXPECT_EQ(grid(31, 1), 15.0 / 16);
  request.params["strata"] = "4x4";
  EXPECT_NE(error_of("grid", request).find("product of strata=4x4"), std::string::npos);
  request.params["strata"] = "4x8x1";
  EXPECT_NE(error_of("grid", request).find("one count per dimension"), std::string::npos);
  request.params["strata"] = "4xz";
  EXPECT_NE(error_of("grid", request).find("invalid strata[1] = z: must be an integer in [1, inf)"), std::string::npos);
  const std::string message = error_of("jittered", request_of(10, 2));
  EXPECT_NE(message.find("n = 10"), std::string::npos) << message;
  EXPECT_NE(message.find("9 = 3^2, 16 = 4^2"), std::string::npos) << message;
}

TEST(PatternRegistry, CranleyPattersonRotatesTheGridModuloOne) {
  auto request = request_of(16, 2, 5);
  const PointSet plain = generate_points("grid", request);
  request.randomize = "cp";
  const PointSet rotated = generate_points("grid", request);
  for (std::size_t j = 0; j < 2; ++j) {
    const double shift = std::fmod(rotated(0, j) - plain(0, j) + 1.0, 1.0);
    for (std::size_t i = 0; i < 16; ++i) EXPECT_NEAR(std::fmod(plain(i, j) + shift, 1.0), rotated(i, j), 1e-15);
  }
}

TEST(PatternRegistry, BadCountsNameNAndTheAllowedValues) {
  std::string message = error_of("n-queens", request_of(3, 2));
  EXPECT_NE(message.find("n = 3"), std::string::npos) << message;
  EXPECT_NE(message.find("n = 1 or n >= 4"), std::string::npos) << message;
  message = error_of("latin-square", request_of(50, 3));
  EXPECT_NE(message.find("n = 50"), std::string::npos) << message;
  EXPECT_NE(message.find("n = m^2"), std::string::npos) << message;
  EXPECT_NE(message.find("49, 64"), std::string::npos) << message;
  auto mj = request_of(30, 2);
  mj.params["strata"] = "4x8";
  message = error_of("multi-jittered", mj);
  EXPECT_NE(message.find("n = 30"), std::string::npos) << message;
  message = error_of("cmj", request_of(1ull << 32, 2));
  EXPECT_NE(message.find("2^32 - 1"), std::string::npos) << message;
  auto square = request_of(1000000, 3);
  message = error_of("latin-square", square);
  EXPECT_NE(message.find("permuted-cyclic"), std::string::npos) << message;
  square.params["method"] = "permuted-cyclic";
  EXPECT_EQ(error_of("latin-square", square), "");
  square.params["method"] = "magic";
  EXPECT_NE(error_of("latin-square", square).find("method = magic"), std::string::npos);
}

TEST(PatternRegistry, MultiJitteredStrataParameter) {
  auto request = request_of(32, 2, 3);
  request.params["strata"] = "8x4";
  const PointSet points = generate_points("multi-jittered", request);
  std::vector<int> strata(32, 0);
  for (std::size_t i = 0; i < 32; ++i)
    ++strata[static_cast<std::size_t>(points(i, 1) * 4) * 8 + static_cast<std::size_t>(points(i, 0) * 8)];
  for (int h : strata) EXPECT_EQ(h, 1);
}

TEST(PatternRegistry, LatinSquareIsThreeDimensional) {
  const PointSet points = generate_points("latin-square", request_of(25, 3));
  ASSERT_EQ(points.n, 25u);
  std::vector<int> row_symbol(25, 0);
  for (std::size_t i = 0; i < 25; ++i)
    ++row_symbol[static_cast<std::size_t>(points(i, 0) * 5) * 5 + static_cast<std::size_t>(points(i, 2) * 5)];
  for (int h : row_symbol) EXPECT_EQ(h, 1);
  EXPECT_NE(error_of("latin-square", request_of(25, 2)).find("d = 2"), std::string::npos);
}

// Large requests stay identical across thread counts where the work is split
// (n-rooks conversion, multi-jittered columns), beyond one 4096-row chunk.
TEST(PatternRegistry, LargeSetsAreThreadInvariant) {
  for (const std::string name : {"n-rooks", "multi-jittered", "cmj", "n-queens", "jittered", "latin-square"}) {
    const unsigned d = name == "latin-square" ? 3 : name == "jittered" ? 1 : 2;
    auto request = request_of(40000, d, 9);
    if (name == "multi-jittered") {  // 8192 columns: two chunks of 4096
      request.n = 8192 * 32;
      request.params["strata"] = "8192x32";
    }
    if (name == "latin-square") request.params["method"] = "permuted-cyclic";
    const PointSet one = generate_points(name, request);
    request.threads = 2;
    const PointSet two = generate_points(name, request);
    EXPECT_EQ(0, std::memcmp(one.data.get(), two.data.get(), one.n * one.d * sizeof(double))) << name;
  }
}

// n-queens by default: E[1[x + y < 0.6]] = 0.18 for uniform points. The
// unrotated random solutions read 0.2070 ± 0.0011 at n = 8 (their cells are
// not occupied with probability exactly 1/n); the default (cp) is unbiased.
// 4000 seeds, two-sided t-test at level 0.001.
TEST(PatternRegistry, NQueensDefaultIsUnbiased) {
  EXPECT_EQ(find_sampler("n-queens").randomizers.front(), "cp");
  std::vector<double> estimates;
  for (std::uint64_t seed = 0; seed < 4000; ++seed) {
    const PointSet points = generate_points("n-queens", request_of(8, 2, seed));
    double below = 0;
    for (std::size_t i = 0; i < 8; ++i) below += points.data[2 * i] + points.data[2 * i + 1] < 0.6 ? 1 : 0;
    estimates.push_back(below / 8);
  }
  testing::expect_unbiased("n-queens default, n = 8", estimates, 0.18, 0.001);
}

// random is index-addressable and progressive: point i of start K is point
// K + i of a longer run, also past 2^32; the other finite patterns refuse start.
TEST(PatternRegistry, RandomTakesStart) {
  SamplerRequest longer = request_of(40, 3, 9);
  longer.start = (std::uint64_t{1} << 32) - 10;
  const PointSet all = generate_points("random", longer);
  SamplerRequest tail = request_of(25, 3, 9);
  tail.start = longer.start + 15;
  const PointSet part = generate_points("random", tail);
  for (std::size_t k = 0; k < 25 * 3; ++k) EXPECT_EQ(part.data[k], all.data[15 * 3 + k]) << k;
  SamplerRequest from_zero = request_of(20, 3, 9);
  const PointSet head = generate_points("random", from_zero);
  from_zero.start = 5;
  from_zero.n = 15;
  const PointSet shifted = generate_points("random", from_zero);
  for (std::size_t k = 0; k < 15 * 3; ++k) EXPECT_EQ(shifted.data[k], head.data[5 * 3 + k]) << k;
  SamplerRequest jittered = request_of(16, 2);
  jittered.start = 1;
  EXPECT_NE(error_of("jittered", jittered).find("invalid start = 1: jittered is a finite pattern"), std::string::npos);
}

}  // namespace
}  // namespace stratum
