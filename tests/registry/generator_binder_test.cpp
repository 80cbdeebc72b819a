// GeneratorBinder (registry/generator_binder.hpp): validated once, then
// bound per seed and start; its generators draw what bind_generator's do.
#include "stratum/registry/generator_binder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>

#include "stratum/registry.hpp"
#include "stratum/util/error.hpp"

using namespace stratum;

TEST(GeneratorBinder, BindsWhatBindGeneratorBindsForEverySeedAndStart) {
  int compared = 0;
  for (const SamplerInfo& info : samplers()) {
    if (!info.bind) continue;
    const unsigned d = std::max(2u, info.min_dim);
    SamplerRequest request;
    request.n = 16, request.d = d;
    try {
      validate_request(info, request);
    } catch (const invalid_argument&) {
      continue;  // a sampler that takes no 16-point set (its own tests cover it)
    }
    for (const std::string& randomize : info.randomizers) {
      request.randomize = randomize;
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
