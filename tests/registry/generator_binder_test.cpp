// GeneratorBinder (registry/generator_binder.hpp): validated once, then
// bound per seed and start; its generators draw what bind_generator's do.
#include "stratum/registry/generator_binder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "stratum/registry.hpp"
#include "stratum/util/error.hpp"

using namespace stratum;

namespace {
/// A 16-point request in the sampler's smallest dimension (at least 2) under
/// each of its randomizers, for every sampler that binds a generator and
/// takes 16 points (the others' own tests cover them).
std::vector<std::pair<const SamplerInfo*, SamplerRequest>> bindable_requests() {
  std::vector<std::pair<const SamplerInfo*, SamplerRequest>> requests;
  for (const SamplerInfo& info : samplers()) {
    if (!info.bind) continue;
    SamplerRequest request;
    request.n = 16, request.d = std::max(2u, info.min_dim);
    try {
      validate_request(info, request);
    } catch (const invalid_argument&) {
      continue;
    }
    for (const std::string& randomize : info.randomizers) {
      request.randomize = randomize;
      requests.emplace_back(&info, request);
    }
  }
  return requests;
}
/// A request in the sampler's smallest dimension (at least 2) for 16 points,
/// or 64 where it does not take 16 (n left empty where it takes neither).
SamplerRequest request_taking_16_or_64(const SamplerInfo& info) {
  SamplerRequest request;
  request.d = std::max(2u, info.min_dim);
  for (const std::uint64_t n : {16ull, 64ull}) {
    request.n = n;
    try {
      validate_request(info, request);
      return request;
    } catch (const invalid_argument&) {
      request.n.reset();
    }
  }
  return request;
}
}  // namespace

TEST(GeneratorBinder, BindsWhatBindGeneratorBindsForEverySeedAndStart) {
  int compared = 0;
  for (const auto& [sampler, request] : bindable_requests()) {
    const SamplerInfo& info = *sampler;
    const unsigned d = request.d;
    const std::string& randomize = request.randomize;
    GeneratorBinder binder(info.name, request);
    EXPECT_EQ(binder.count(), 16u);
    const bool continues = info.kind == "sequence" || info.flags.progressive;
    for (const std::uint64_t seed : {0ull, 3ull, 0xfeedfacecafebeefull})
      for (const std::uint64_t start : {0ull, 32ull}) {
        if (start != 0 && !continues) continue;
        SamplerRequest fresh = request;
        fresh.seed = seed, fresh.start = start;
        const PointGenerator expected = bind_generator(info.name, fresh);
        const PointGenerator got = binder.bind(seed, start);
        for (std::uint64_t i = start; i < start + 16; ++i)
          for (unsigned j = 0; j < d; ++j)
            ASSERT_EQ(got.sample(i, j), expected.sample(i, j)) << info.name << ":" << randomize << " " << seed;
        ++compared;
      }
  }
  EXPECT_GE(compared, 60);
}

TEST(GeneratorBinder, ValidatesOnceAtConstructionWithTheRegistrysMessages) {
  SamplerRequest request;
  request.n = 7, request.d = 2;
  EXPECT_THROW(GeneratorBinder("jittered", request), invalid_argument);  // 7 is not k^2
  request.n = 16;
  request.randomize = "owen";
  EXPECT_THROW(GeneratorBinder("random", request), invalid_argument);  // random takes no randomizer
  request.randomize = "";
  EXPECT_THROW(GeneratorBinder("poisson-disk", request), invalid_argument);  // made as a whole set
  EXPECT_NO_THROW(GeneratorBinder("kronecker", request));
}

TEST(GeneratorBinder, SeededGeneratorsDrawWhatTheirBindingsDraw) {
  // Where a sampler has a SeededGenerator (base-b owen; the constructions
  // that do not depend on the seed, under none and cp; cmj's, the keys of
  // Kensler's pattern; n-queens', its solution's cells), a seed's state written in place gives bind's points, for the
  // leading coordinates asked and for all of them; other randomizers have
  // none (bind stays the path).
  std::set<std::string> seeded;
  for (const auto& [sampler, request] : bindable_requests()) {
    const SamplerInfo& info = *sampler;
    const unsigned d = request.d;
    const std::string& randomize = request.randomize;
    const GeneratorBinder binder(info.name, request);
    if (!binder.seeded()) continue;
    seeded.insert(info.name + ":" + randomize);
    const SeededGenerator& generator = *binder.seeded();
    std::vector<std::uint64_t> state(generator.state_words());
    for (const std::uint64_t seed : {0ull, 3ull, 0xfeedfacecafebeefull})
      for (const unsigned coordinates : {1u, d}) {
        generator.seed(seed, coordinates, state.data());
        SamplerRequest fresh = request;
        fresh.seed = seed;
        const PointGenerator expected = bind_generator(info.name, fresh);
        std::vector<double> block(12 * coordinates);  // points 4 … 15 in one call
        generator.points(state.data(), 4, 12, coordinates, block.data());
        for (std::uint64_t i = 0; i < 16; ++i) {
          std::vector<double> point(coordinates);
          generator.point(state.data(), i, coordinates, point.data());
          for (unsigned j = 0; j < coordinates; ++j) {
            ASSERT_EQ(point[j], expected.sample(i, j)) << info.name << ":" << randomize << " " << seed << " " << i;
            if (i >= 4) ASSERT_EQ(block[(i - 4) * coordinates + j], point[j]) << info.name << " " << i;
          }
        }
      }
  }
  EXPECT_EQ(seeded,
            (std::set<std::string>{"faure:owen", "halton:owen", "grid:none", "grid:cp", "zaremba:none", "zaremba:cp",
                                   "kronecker:none", "kronecker:cp", "lattice-sequence:none", "lattice-sequence:cp",
                                   "cmj:none", "fibonacci:none", "fibonacci:cp", "lattice:none", "lattice:cp",
                                   "hammersley:permute", "n-queens:none", "n-queens:cp"}));
}

TEST(GeneratorBinder, CmjsSeededPointsEqualBindsInEachFormOfItsState) {
  // cmj's state is the points themselves up to n = 64, then its column and
  // row permutations up to 64 columns and rows together (n = 1024 at aspect
  // 1: 32 + 32), beyond that only the keys: each gives bind's points, at
  // counts on either side of both limits, square or not.
  for (const std::uint64_t n : {1ull, 2ull, 3ull, 17ull, 64ull, 65ull, 1023ull, 1024ull, 1025ull, 1089ull})
    for (const char* aspect : {"1", "2.7"}) {
      SamplerRequest request;
      request.n = n, request.d = 2, request.params = {{"aspect", aspect}};
      const GeneratorBinder binder("cmj", request);
      ASSERT_TRUE(binder.seeded());
      const SeededGenerator& generator = *binder.seeded();
      std::vector<std::uint64_t> state(generator.state_words());
      std::vector<double> points(2 * n);
      for (const std::uint64_t seed : {5ull, 0xfeedfacecafebeefull}) {
        generator.seed(seed, 2, state.data());
        generator.points(state.data(), 0, n, 2, points.data());
        SamplerRequest fresh = request;
        fresh.seed = seed;
        const PointGenerator expected = bind_generator("cmj", fresh);
        for (std::uint64_t i = 0; i < n; ++i)
          for (unsigned j = 0; j < 2; ++j)
            ASSERT_EQ(points[2 * i + j], expected.sample(i, j)) << n << " " << aspect << " " << seed << " " << i;
      }
    }
}

TEST(SetBinder, GeneratesWhatGeneratePointsGeneratesForEverySeed) {
  // Every sampler (those made as a whole set too) at a count it takes, under
  // each randomizer: validated once, its sets per seed equal generate_points'.
  int compared = 0;
  for (const SamplerInfo& info : samplers()) {
    const unsigned d = std::max(2u, info.min_dim);
    SamplerRequest request = request_taking_16_or_64(info);
    ASSERT_TRUE(request.n.has_value()) << info.name << " takes none of the counts tried";
    for (const std::string& randomize : info.randomizers) {
      request.randomize = randomize;
      SetBinder binder(info.name, request);
      EXPECT_EQ(binder.count(), *request.n);
      EXPECT_EQ(binder.dimensions(), d);
      for (const std::uint64_t seed : {0ull, 5ull, 0xfeedfacecafebeefull}) {
        const PointSet got = binder.generate(seed);
        SamplerRequest fresh = request;
        fresh.seed = seed;
        const PointSet expected = generate_points(info.name, fresh);
        ASSERT_EQ(got.n, expected.n) << info.name;
        ASSERT_EQ(got.d, expected.d) << info.name;
        for (std::size_t k = 0; k < got.n * got.d; ++k)
          ASSERT_EQ(got.data[k], expected.data[k]) << info.name << ":" << randomize << " " << seed << " " << k;
        ++compared;
      }
    }
  }
  EXPECT_GE(compared, 3 * static_cast<int>(samplers().size()));
  SamplerRequest bad;
  bad.n = 7, bad.d = 2;
  EXPECT_THROW(SetBinder("jittered", bad), invalid_argument);  // 7 is not k^2
}

TEST(SetBinder, SeededPatternsDrawWhatGenerateDraws) {
  // A pattern made as a whole set may write a seed's construction into a
  // SeededGenerator's state (n-rooks its permutations, multi-jittered its
  // fine cells, latin-square its symbols, only where coordinate 2 is asked):
  // point and points then give generate_points' set, for the leading
  // coordinates asked and for all, at several counts, dimensions and
  // parameters. Samplers with a per-point generator keep GeneratorBinder's.
  struct Case {
    const char* name;
    std::uint64_t n;
    unsigned d;
    std::map<std::string, std::string> params;
  };
  const std::vector<Case> cases = {
      {"n-rooks", 1, 1, {}},
      {"n-rooks", 4, 2, {}},
      {"n-rooks", 37, 5, {}},
      {"n-rooks", 16, 3, {{"centered", "1"}}},
      {"latin-hypercube", 9, 2, {}},
      {"multi-jittered", 4, 2, {}},
      {"multi-jittered", 7, 2, {}},
      {"multi-jittered", 24, 2, {{"strata", "6x4"}}},
      {"latin-square", 4, 3, {}},
      {"latin-square", 49, 3, {}},
      {"latin-square", 25, 3, {{"method", "permuted-cyclic"}}},
  };
  for (const Case& c : cases) {
    SamplerRequest request;
    request.n = c.n, request.d = c.d, request.params = c.params;
    const SetBinder binder(c.name, request);
    ASSERT_TRUE(binder.seeded()) << c.name;
    const SeededGenerator& generator = *binder.seeded();
    std::vector<std::uint64_t> state(generator.state_words());
    for (const std::uint64_t seed : {0ull, 3ull, 0xfeedfacecafebeefull}) {
      SamplerRequest fresh = request;
      fresh.seed = seed;
      const PointSet expected = generate_points(c.name, fresh);
      for (unsigned coordinates = 1; coordinates <= c.d; ++coordinates) {
        std::fill(state.begin(), state.end(), 0);  // nothing left from the last seed
        generator.seed(seed, coordinates, state.data());
        std::vector<double> all(c.n * coordinates), point(coordinates);
        const std::uint64_t half = c.n / 2;  // two calls: points from a first index other than 0 too
        generator.points(state.data(), 0, half, coordinates, all.data());
        generator.points(state.data(), half, c.n - half, coordinates, all.data() + half * coordinates);
        for (std::uint64_t i = 0; i < c.n; ++i) {
          generator.point(state.data(), i, coordinates, point.data());
          for (unsigned j = 0; j < coordinates; ++j) {
            ASSERT_EQ(point[j], expected(i, j)) << c.name << " n " << c.n << " seed " << seed << " " << i << "," << j;
            ASSERT_EQ(all[i * coordinates + j], point[j]) << c.name << " " << i;
          }
        }
      }
    }
  }
  // The exact set of whole-set patterns with one, so a new one is tested here.
  std::set<std::string> seeded;
  for (const SamplerInfo& info : samplers()) {
    if (info.bind) continue;
    SamplerRequest request = request_taking_16_or_64(info);
    ASSERT_TRUE(request.n.has_value()) << info.name;
    for (const std::string& randomize : info.randomizers) {
      request.randomize = randomize;
      if (SetBinder(info.name, request).seeded()) seeded.insert(info.name + ":" + randomize);
    }
  }
  EXPECT_EQ(seeded, (std::set<std::string>{"n-rooks:none", "latin-hypercube:none", "multi-jittered:none",
                                           "latin-square:none"}));
}
