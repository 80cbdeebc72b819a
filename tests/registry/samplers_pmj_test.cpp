// Registry entry "pmj02" (src/registry/samplers_pmj.cpp).
#include <gtest/gtest.h>

#include <algorithm>

#include "stratum/registry.hpp"
#include "stratum/sequences/pmj.hpp"
#include "stratum/util/error.hpp"

namespace stratum {
namespace {

TEST(SamplersPmj, MatchesTheHeaderAndHonoursStart) {
  SamplerRequest request;
  request.n = 64;
  request.d = 3;
  request.seed = 3;
  request.start = 1000;
  const PointSet points = generate_points("pmj02", request);
  const Pmj02 pmj(3, 3);
  for (std::size_t i = 0; i < 64; ++i)
    for (unsigned j = 0; j < 3; ++j) ASSERT_EQ(points(i, j), pmj.sample(1000 + i, j));
}

TEST(SamplersPmj, EntryDescribesItself) {
  const SamplerInfo& info = find_sampler("pmj02");
  EXPECT_EQ(info.kind, "sequence");
  EXPECT_EQ(info.randomizers, std::vector<std::string>{"none"});
  EXPECT_TRUE(info.flags.index_addressable);
  EXPECT_TRUE(info.flags.progressive);
  EXPECT_TRUE(info.flags.zero_two_net);
  const std::vector<std::string> words = property_words(info);
  for (const char* p : {"index-addressable", "progressive", "(0,2)-sequence", "multi-jittered"})
    EXPECT_NE(std::find(words.begin(), words.end(), p), words.end()) << p;
  EXPECT_NE(info.description.find("Owen"), std::string::npos);
  SamplerRequest request;
  request.n = 16;
  request.d = 65;
  EXPECT_THROW(generate_points("pmj02", request), invalid_argument);
  request.d = 2;
  request.randomize = "cp";  // would break the elementary intervals
  EXPECT_THROW(generate_points("pmj02", request), invalid_argument);
}

}  // namespace
}  // namespace stratum
