#include "stratum/memory.hpp"
#include "stratum/registry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <set>

#include "stratum/util/error.hpp"

namespace stratum {
namespace {

SamplerRequest request_of(std::uint64_t n, unsigned d) {
  SamplerRequest request;
  request.n = n;
  request.d = d;
  return request;
}

TEST(Registry, NamesAreUniqueAndEntriesComplete) {
  std::set<std::string> names;
  for (const auto& s : samplers()) {
    EXPECT_TRUE(names.insert(s.name).second) << s.name;
    EXPECT_FALSE(s.description.empty()) << s.name;
    EXPECT_TRUE(s.kind == "sequence" || s.kind == "pattern") << s.name;
    EXPECT_LE(s.min_dim, s.max_dim) << s.name;
    EXPECT_FALSE(s.randomizers.empty()) << s.name;
    EXPECT_TRUE(s.count && s.generate) << s.name;
    for (const auto& r : s.randomizers)
      EXPECT_TRUE(std::any_of(randomizers().begin(), randomizers().end(), [&](auto& p) { return p.first == r; }))
          << s.name << " lists unknown randomizer " << r;
  }
}

TEST(Registry, UnknownSamplerListsValidNames) {
  try {
    find_sampler("sobbol");
    FAIL() << "no exception";
  } catch (const invalid_argument& e) {
    EXPECT_EQ(e.argument(), "sampler");
    EXPECT_NE(std::string(e.what()).find("sobbol"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("halton"), std::string::npos);
  }
}

TEST(Registry, BadDimensionNamesTheRange) {
  try {
    generate_points("halton", request_of(4, 5000));
    FAIL() << "no exception";
  } catch (const invalid_argument& e) {
    EXPECT_EQ(e.argument(), "d");
    EXPECT_NE(std::string(e.what()).find("5000"), std::string::npos);
  }
}

TEST(Registry, RefusesHugeRequestsBeforeAllocating) {
  try {
    generate_points("random", request_of(std::uint64_t{1} << 60, 4));
    FAIL() << "no exception";
  } catch (const memory_error& e) {  // the memory guard (stratum/memory.hpp), before any allocation
    EXPECT_NE(std::string(e.what()).find("needs 32.0 EiB for 1152921504606846976 x 4 points of random, "),
              std::string::npos)
        << e.what();
  }
}

TEST(Registry, RejectsUnknownRandomizerAndParams) {
  auto request = request_of(4, 2);
  request.randomize = "shuffle";
  EXPECT_THROW(generate_points("halton", request), invalid_argument);
  request.randomize = "";
  request.params["bogus"] = "1";
  EXPECT_THROW(generate_points("halton", request), invalid_argument);
}

TEST(Registry, MissingNIsAnErrorUnlessRadiusDrives) {
  SamplerRequest request;
  request.d = 2;
  EXPECT_THROW(generate_points("halton", request), invalid_argument);
}

// Every sampler, at a count it accepts, produces points in [0,1)^d, and the
// same bits with 1 and 2 threads.
TEST(Registry, EverySamplerFillsTheUnitCubeIdenticallyOnOneAndTwoThreads) {
  for (const auto& s : samplers()) {
    int counts_taken = 0;  // a sampler that takes none of the counts would be skipped silently
    for (std::uint64_t n : {1ull, 16ull, 64ull, 256ull, 10000ull, 16384ull}) {
      auto request = request_of(n, std::clamp(3u, s.min_dim, s.max_dim));
      request.seed = 7;
      try {
        validate_request(s, request);
      } catch (const invalid_argument&) {
        continue;  // this sampler does not take this n
      }
      ++counts_taken;
      const PointSet one = generate_points(s.name, request);
      request.threads = 2;
      const PointSet two = generate_points(s.name, request);
      ASSERT_EQ(one.n, two.n) << s.name;
      ASSERT_EQ(one.d, request.d) << s.name;
      for (std::size_t k = 0; k < one.n * one.d; ++k) {
        ASSERT_GE(one.data[k], 0.0) << s.name << " n=" << n;
        ASSERT_LT(one.data[k], 1.0) << s.name << " n=" << n;
      }
      EXPECT_EQ(0, std::memcmp(one.data.get(), two.data.get(), one.n * one.d * sizeof(double)))
          << s.name << " differs between 1 and 2 threads at n=" << n;
    }
    EXPECT_GT(counts_taken, 0) << s.name << " takes none of the counts tried: add one it takes";
  }
}

}  // namespace
}  // namespace stratum
