// The registry's typed flags (SamplerFlags) checked against every sampler's
// points: code relies on them (the renderer's frames and shadow-ray arrays,
// compare's equal-time passes, the registry's `start` rule), so each flag a
// sampler claims is a property of its sets, and a flag it lacks is not
// silently assumed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "../patterns/unbiased.hpp"
#include "registry_points.hpp"
#include "stratum/registry.hpp"
#include "stratum/util/error.hpp"

namespace stratum {
namespace {

using testing::sampler_points;

unsigned dims_for(const SamplerInfo& s) { return std::clamp(2u, s.min_dim, s.max_dim); }

/// The smallest of a few counts the sampler takes (16, 64, 256: squares, powers of 2 and 4).
std::optional<std::uint64_t> count_for(const SamplerInfo& s, const std::string& randomize) {
  for (std::uint64_t n : {16ull, 64ull, 256ull}) {
    SamplerRequest request;
    request.n = n;
    request.d = dims_for(s);
    request.randomize = randomize;
    try {
      validate_request(s, request);
      return n;
    } catch (const invalid_argument&) {
    }
  }
  return std::nullopt;
}

bool same_bits(const PointSet& a, const PointSet& b) {
  return a.n == b.n && a.d == b.d && std::memcmp(a.data.get(), b.data.get(), a.n * a.d * sizeof(double)) == 0;
}

bool accepts(const SamplerInfo& s, const std::string& randomize) {
  return std::find(s.randomizers.begin(), s.randomizers.end(), randomize) != s.randomizers.end();
}

TEST(SamplerFlags, AgreeWithTheRandomizersEachSamplerAccepts) {
  for (const SamplerInfo& s : samplers()) {
    ASSERT_FALSE(s.randomizers.empty()) << s.name;
    if (!s.flags.self_randomized) {
      EXPECT_TRUE(accepts(s, "none")) << s.name << " is a deterministic construction: it must accept none";
    }
    for (const std::string& r : s.flags.prefix_unbiased) EXPECT_TRUE(accepts(s, r)) << s.name << " " << r;
    if (s.flags.frames_continue) EXPECT_FALSE(s.flags.progressive) << s.name << ": a pixel sampler's start is a frame";
    if (s.flags.space_time) {
      EXPECT_EQ(s.min_dim, 3u) << s.name << ": (x, y, t)";
      EXPECT_EQ(s.max_dim, 3u) << s.name << ": (x, y, t)";
    }
  }
}

TEST(SamplerFlags, ProgressiveSamplersContinueTheirSequenceAtStart) {
  int checked = 0;
  for (const SamplerInfo& s : samplers()) {
    if (!s.flags.progressive) continue;
    for (const std::string& r : s.randomizers) {
      const auto n = count_for(s, r);
      ASSERT_TRUE(n) << s.name << " takes none of the counts tried";
      const unsigned d = dims_for(s);
      const PointSet whole = sampler_points(s.name, 2 * *n, d, r, 5);
      const PointSet tail = sampler_points(s.name, *n, d, r, 5, *n);
      ASSERT_EQ(tail.n, *n) << s.name;
      EXPECT_EQ(0, std::memcmp(tail.data.get(), whole.data.get() + *n * d, *n * d * sizeof(double)))
          << s.name << ":" << r << ": points from start " << *n << " are not rows " << *n << ".. of the longer set";
      ++checked;
    }
  }
  EXPECT_GE(checked, 20);  // sobol, halton, faure, pmj02, random, ... with their randomizers
}

TEST(SamplerFlags, OnlyProgressiveSamplersSequencesAndPixelSamplersTakeAStart) {
  for (const SamplerInfo& s : samplers()) {
    const auto n = count_for(s, "");
    ASSERT_TRUE(n) << s.name;
    SamplerRequest request;
    request.n = *n;
    request.d = dims_for(s);
    request.start = *n;
    const bool takes_start = s.kind == "sequence" || s.flags.progressive || s.flags.frames_continue;
    if (takes_start) {
      EXPECT_NO_THROW(validate_request(s, request)) << s.name;
      if (s.flags.frames_continue)  // a later frame of the pixel: other points
        EXPECT_FALSE(
            same_bits(sampler_points(s.name, *n, request.d, "", 3, *n), sampler_points(s.name, *n, request.d, "", 3)))
            << s.name;
    } else {
      EXPECT_THROW(validate_request(s, request), invalid_argument) << s.name;
    }
  }
}

TEST(SamplerFlags, SelfRandomizedSamplersChangeWithTheSeedDeterministicOnesDoNotUnderNone) {
  for (const SamplerInfo& s : samplers()) {
    const unsigned d = dims_for(s);
    const auto n = count_for(s, "");
    ASSERT_TRUE(n) << s.name;
    const bool seeds_differ = !same_bits(sampler_points(s.name, *n, d, "", 1), sampler_points(s.name, *n, d, "", 2));
    if (s.flags.self_randomized) {
      EXPECT_TRUE(seeds_differ) << s.name << " claims to be self-randomized, but seeds 1 and 2 give the same points";
    } else {
      const auto m = count_for(s, "none");
      ASSERT_TRUE(m) << s.name;
      EXPECT_TRUE(same_bits(sampler_points(s.name, *m, d, "none", 1), sampler_points(s.name, *m, d, "none", 2)))
          << s.name << " under none depends on the seed: it is self-randomized";
      if (s.randomizers.front() != "none")
        EXPECT_TRUE(seeds_differ) << s.name << "'s default randomizer ignores the seed";
    }
  }
}

/// Whether dimensions 0 and 1 of the n = 2^m points put one point in every
/// elementary interval [a/2^k, (a+1)/2^k) × [b/2^(m−k), (b+1)/2^(m−k)).
bool is_zero_m_two_net(const PointSet& p, unsigned m) {
  for (unsigned k = 0; k <= m; ++k) {
    std::vector<int> cells(std::size_t{1} << m, 0);
    for (std::size_t i = 0; i < p.n; ++i) {
      const auto a = static_cast<std::size_t>(p(i, 0) * double(1u << k));
      const auto b = static_cast<std::size_t>(p(i, 1) * double(1u << (m - k)));
      if (++cells[(a << (m - k)) | b] > 1) return false;
    }
  }
  return true;
}

TEST(SamplerFlags, ZeroTwoNetsHoldAtEveryPowerOfTwoAndTheFlagIsNotFree) {
  int nets = 0;
  for (const SamplerInfo& s : samplers()) {
    if (!s.flags.zero_two_net) continue;
    for (const std::string& r : s.randomizers) {
      if (r == "cp") continue;  // a rotation moves points across interval boundaries
      for (unsigned m : {4u, 6u, 8u}) {
        const PointSet p = sampler_points(s.name, std::uint64_t{1} << m, dims_for(s), r, 9);
        EXPECT_TRUE(is_zero_m_two_net(p, m)) << s.name << ":" << r << " at n = 2^" << m;
        ++nets;
      }
    }
  }
  EXPECT_GE(nets, 3 * 12);  // sobol (5 randomizers), zero-two (5), pmj02, pmj02bn
  // The check can fail: random points and Halton's (base 2 × 3) are no (0,m,2)-nets in base 2.
  EXPECT_FALSE(is_zero_m_two_net(sampler_points("random", 64, 2, "", 9), 6));
  EXPECT_FALSE(is_zero_m_two_net(sampler_points("halton", 64, 2, "none", 9), 6));
  EXPECT_FALSE(find_sampler("halton").flags.zero_two_net);
}

TEST(SamplerFlags, UnderAPrefixUnbiasedRandomizerEachPointIsUniform) {
  // A t-test per (sampler, randomizer, point, coordinate) that E x = 1/2 and
  // E x² = 1/3 over 400 seeds, at family level 0.01 with Šidák's correction.
  struct Case {
    std::string sampler, randomize;
  };
  std::vector<Case> cases;
  for (const SamplerInfo& s : samplers())
    for (const std::string& r : s.flags.prefix_unbiased) cases.push_back({s.name, r});
  ASSERT_GE(cases.size(), 2u);
  const std::vector<std::size_t> points{0, 1, 5, 11};
  const int tests = static_cast<int>(cases.size() * points.size() * 2 * 2);
  const double alpha = testing::sidak(0.01, tests);
  for (const Case& c : cases) {
    for (std::size_t i : points) {
      for (unsigned j = 0; j < 2; ++j) {
        std::vector<double> x, x2;
        for (std::uint64_t seed = 0; seed < 400; ++seed) {
          const double v = sampler_points(c.sampler, 16, 2, c.randomize, 7000 + seed)(i, j);
          x.push_back(v), x2.push_back(v * v);
        }
        const std::string what =
            c.sampler + ":" + c.randomize + " point " + std::to_string(i) + " coordinate " + std::to_string(j);
        testing::expect_unbiased(what + " mean", x, 0.5, alpha);
        testing::expect_unbiased(what + " second moment", x2, 1.0 / 3.0, alpha);
      }
    }
  }
}

TEST(SamplerFlags, ListingsSpellTheFlagsOut) {
  const std::vector<std::string> words = property_words(find_sampler("zsobol"));
  EXPECT_NE(std::find(words.begin(), words.end(), frames_continue_property), words.end());
  EXPECT_NE(std::find(words.begin(), words.end(), "self-randomized"), words.end());
  EXPECT_TRUE(prefix_unbiased(find_sampler("sobol"), ""));  // its default, owen-hash
  EXPECT_FALSE(prefix_unbiased(find_sampler("sobol"), "none"));
  EXPECT_FALSE(prefix_unbiased(find_sampler("jittered"), ""));
}

}  // namespace
}  // namespace stratum
