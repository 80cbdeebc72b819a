// Keyed pairs (patterns/keyed_pairs.hpp) against the registry: for every
// sampler and randomizer the registry gives keyed pairs for, point i of the
// set of seed s is row i of generate_points(name, {n, d = 2, s, start}),
// bit for bit, for several n, seeds and starts; and the samplers the
// renderer's direct path relies on have them.
#include "stratum/patterns/keyed_pairs.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <set>
#include <string>
#include <variant>

#include "stratum/patterns/strata.hpp"
#include "stratum/registry.hpp"

namespace {

using namespace stratum;

/// Checks the keyed points of `pairs` against the registry's set, or that
/// both refuse the count; returns how many sets were compared.
int check(const SamplerInfo& info, const std::string& randomizer, const KeyedPairs& keyed) {
  int compared = 0;
  for (const std::uint64_t n : {1u, 4u, 7u, 16u, 64u}) {
    const std::uint64_t root = integer_root(n, 2);
    const bool takes = std::visit([&](const auto& pairs) { return pairs.takes(n, root); }, keyed.pairs);
    for (const std::uint64_t seed : {0ull, 1ull, 0x9e3779b97f4a7c15ull}) {
      for (const std::uint64_t start : {0ull, 5ull}) {
        if (start != 0 && !info.flags.progressive) continue;
        SamplerRequest request;
        request.n = n, request.d = 2, request.seed = seed, request.start = start, request.randomize = randomizer;
        if (!takes) {
          EXPECT_THROW(generate_points(info.name, request), invalid_argument) << info.name << " n = " << n;
          continue;
        }
        const PointSet set = generate_points(info.name, request);
        std::visit(
            [&](const auto& pairs) {
              const PairKey key = pairs.key(seed);
              for (std::uint64_t i = 0; i < n; ++i) {
                const auto both = pairs.template point<2>(key, root, start + i);
                const auto first = pairs.template point<1>(key, root, start + i);
                ASSERT_EQ(both[0], set(i, 0)) << info.name << ":" << randomizer << " n " << n << " i " << i;
                ASSERT_EQ(both[1], set(i, 1)) << info.name << ":" << randomizer << " n " << n << " i " << i;
                ASSERT_EQ(first[0], both[0]);
              }
            },
            keyed.pairs);
        ++compared;
      }
    }
  }
  return compared;
}

}  // namespace

TEST(KeyedPairs, EqualTheRegistrysSetsWhereTheRegistryGivesThem) {
  std::set<std::string> keyed_names;
  for (const SamplerInfo& info : samplers()) {
    if (!info.keyed_pairs) continue;
    for (const std::string& randomizer : info.randomizers) {
      const std::optional<KeyedPairs> keyed = info.keyed_pairs(parse_randomizer(randomizer));
      if (!keyed) continue;
      EXPECT_GT(check(info, randomizer, *keyed), 0) << info.name;
      keyed_names.insert(info.name + ":" + randomizer);
    }
  }
  // What the renderer's direct path is measured with (BENCHMARKS 5): a name
  // or randomizer that changes must fail here, not silently slow renders.
  EXPECT_EQ(keyed_names, (std::set<std::string>{"jittered:none", "pmj02:none", "random:none", "sobol:owen-hash",
                                                "zero-two:owen-hash"}));
}

TEST(KeyedPairs, AreAbsentUnderOtherRandomizers) {
  const SamplerInfo& sobol = find_sampler("sobol");
  ASSERT_TRUE(sobol.keyed_pairs);
  EXPECT_FALSE(sobol.keyed_pairs(Randomizer::none).has_value());
  EXPECT_FALSE(sobol.keyed_pairs(Randomizer::lms).has_value());
  EXPECT_TRUE(sobol.keyed_pairs(Randomizer::owen_hash).has_value());
}
