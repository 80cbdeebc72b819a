// Randomizers as values (Randomizer) and the families that decide which a
// sampler accepts (RandomizerFamily, accepted_randomizers): the names round
// trip, every sampler's list is its family's, and each family's promise
// holds on the points: digit randomizers keep a base-b construction's
// strata, a seeded construction needs no randomizer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "registry_points.hpp"
#include "stratum/registry.hpp"
#include "stratum/sequences/faure.hpp"
#include "stratum/sequences/halton.hpp"
#include "stratum/util/error.hpp"

namespace stratum {
namespace {

TEST(Randomizers, NamesRoundTripAndAnUnknownNameIsRefused) {
  ASSERT_EQ(randomizers().size(), 7u);
  for (const auto& [name, description] : randomizers()) {
    EXPECT_EQ(randomizer_name(parse_randomizer(name)), name);
    EXPECT_FALSE(description.empty()) << name;
  }
  try {
    parse_randomizer("scramble");
    FAIL() << "an unknown randomizer was accepted";
  } catch (const invalid_argument& e) {
    EXPECT_EQ(e.argument(), "randomize");
    EXPECT_NE(std::string(e.what()).find("owen-hash"), std::string::npos) << e.what();
  }
}

TEST(Randomizers, EachSamplerAcceptsItsFamilysRandomizersDefaultFirst) {
  for (const SamplerInfo& s : samplers()) {
    const std::vector<Randomizer> accepted = accepted_randomizers(s.randomization);
    ASSERT_FALSE(accepted.empty()) << s.name;
    EXPECT_EQ(accepted.front(), s.randomization.default_randomizer) << s.name;
    std::vector<std::string> names;
    for (Randomizer r : accepted) names.emplace_back(randomizer_name(r));
    EXPECT_EQ(s.randomizers, names) << s.name;
    // A randomizer outside the family is refused by the request check.
    for (const auto& [name, description] : randomizers()) {
      if (std::find(names.begin(), names.end(), name) != names.end()) continue;
      SamplerRequest request;
      request.n = 16, request.d = std::max(2u, s.min_dim), request.randomize = name;
      EXPECT_THROW(validate_request(s, request), invalid_argument) << s.name << " took " << name;
    }
  }
  // A default outside its family gives no list (the registry refuses such an entry).
  EXPECT_TRUE(accepted_randomizers({RandomizerFamily::rotation, Randomizer::owen}).empty());
}

TEST(Randomizers, FamiliesMatchTheConstructions) {
  for (const SamplerInfo& s : samplers()) {
    const RandomizerFamily family = s.randomization.family;
    // A seeded construction draws from the seed itself.
    if (family == RandomizerFamily::seeded || family == RandomizerFamily::seeded_owen_hash) {
      EXPECT_TRUE(s.flags.self_randomized) << s.name;
    }
    // A (0,2)-net in base 2 is a base-2 digital construction or a seeded one (pmj02).
    if (s.flags.zero_two_net) {
      EXPECT_NE(family, RandomizerFamily::rotation) << s.name;
    }
  }
}

/// Coordinate j's base in a base-b digital construction of d dimensions.
std::uint32_t coordinate_base(const std::string& name, unsigned d, unsigned j) {
  if (name == "halton") return Halton::base(j);
  if (name == "faure") return Faure(d).base();
  if (name == "hammersley") return j == 0 ? 0 : Halton::base(j - 1);  // coordinate 0 is i/N
  ADD_FAILURE() << "a new sampler of family base_b_digits: give its coordinates' bases here";
  return 0;
}

TEST(Randomizers, DigitRandomizersKeepEachCoordinatesBaseBStrata) {
  // The first b^k points of each coordinate, radical inverses of 0..b^k − 1,
  // fall one in each interval [i/b^k, (i+1)/b^k); permute, xor and owen map
  // those intervals onto each other (they act on the digits), so they keep it.
  int checked = 0;
  for (const SamplerInfo& s : samplers()) {
    if (s.randomization.family != RandomizerFamily::base_b_digits) continue;
    const unsigned d = std::min(3u, s.max_dim);
    for (const char* randomize : {"none", "permute", "xor", "owen"}) {
      const PointSet points = testing::sampler_points(s.name, 243, d, randomize, 11);
      for (unsigned j = 0; j < d; ++j) {
        const std::uint32_t base = coordinate_base(s.name, d, j);
        if (base == 0) continue;
        std::uint64_t cells = 1;
        while (cells * base <= 243) cells *= base;
        std::vector<int> count(cells, 0);
        // The unscrambled points lie on the cells' left ends, i/b^k, which a
        // double may round just below: the 1e-9 nudge puts them back.
        for (std::uint64_t i = 0; i < cells; ++i)
          ++count[std::min<std::size_t>(cells - 1, static_cast<std::size_t>(std::floor(points(i, j) * cells + 1e-9)))];
        EXPECT_TRUE(std::all_of(count.begin(), count.end(), [](int c) { return c == 1; }))
            << s.name << ":" << randomize << " coordinate " << j << " base " << base;
        ++checked;
      }
    }
  }
  EXPECT_GE(checked, 3 * 4 * 2);  // halton, hammersley, faure
}

}  // namespace
}  // namespace stratum
