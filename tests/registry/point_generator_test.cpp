// PointGenerator: each index-addressable sampler bound to a request draws
// point i alone, and those are the registry's points bit for bit, under
// every randomizer it accepts (the sets are filled from the generator, or by
// an engine such as Sobol's block walk that must agree with it).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "registry_points.hpp"
#include "stratum/registry.hpp"
#include "stratum/util/error.hpp"

namespace stratum {
namespace {

/// A count the sampler takes (its first accepted of a few).
std::uint64_t count_for(const SamplerInfo& s, unsigned d, const std::string& randomize,
                        const std::map<std::string, std::string>& params) {
  for (std::uint64_t n : {64ull, 16ull, 81ull, 100ull}) {
    SamplerRequest request;
    request.n = n, request.d = d, request.randomize = randomize, request.params = params;
    try {
      validate_request(s, request);
      return n;
    } catch (const invalid_argument&) {
    }
  }
  return 0;
}

TEST(PointGenerator, EveryIndexAddressableSamplerHasOne) {
  for (const SamplerInfo& s : samplers()) {
    if (s.flags.index_addressable) {
      EXPECT_TRUE(static_cast<bool>(s.bind)) << s.name;
    }
  }
}

TEST(PointGenerator, DrawsTheRegistrysPointsBitForBit) {
  // Parameter variants that change the drawing path (Sobol's digits and order, Halton's bases).
  const std::map<std::string, std::vector<std::map<std::string, std::string>>> variants = {
      {"sobol", {{}, {{"bits", "10"}}, {{"order", "natural"}}, {{"bits", "60"}, {"order", "natural"}}}},
      {"zero-two", {{}, {{"bits", "7"}}}},
      {"halton", {{}, {{"bases", "5,7,2"}}}},
  };
  int checked = 0;
  for (const SamplerInfo& s : samplers()) {
    if (!s.bind) continue;
    const unsigned d = std::clamp(3u, s.min_dim, s.max_dim);
    const auto found = variants.find(s.name);
    const std::vector<std::map<std::string, std::string>> params =
        found == variants.end() ? std::vector<std::map<std::string, std::string>>{{}} : found->second;
    for (const auto& p : params)
      for (const std::string& r : s.randomizers) {
        const std::uint64_t n = count_for(s, d, r, p);
        ASSERT_NE(n, 0u) << s.name << ":" << r;
        const bool continues = s.kind == "sequence" || s.flags.progressive;
        const std::uint64_t start = continues ? 1000 : 0;
        const PointSet set = testing::sampler_points(s.name, n, d, r, 77, start, p);
        SamplerRequest request;
        request.n = n, request.d = d, request.randomize = r, request.seed = 77, request.start = start;
        request.params = p;
        const PointGenerator generator = bind_generator(s.name, request);
        ASSERT_EQ(generator.dimensions(), d) << s.name;
        std::vector<double> filled(n * d);
        generator.fill(start, n, filled.data());
        for (std::uint64_t i = 0; i < n; ++i)
          for (unsigned j = 0; j < d; ++j) {
            const double drawn = generator.sample(start + i, j);
            ASSERT_EQ(std::memcmp(&drawn, &set.data[i * d + j], sizeof drawn), 0)
                << s.name << ":" << r << " point " << start + i << " coordinate " << j << ": " << drawn
                << " != " << set(i, j);
            ASSERT_EQ(filled[i * d + j], drawn) << s.name << ":" << r;
          }
        ++checked;
      }
  }
  EXPECT_GE(checked, 40);
}

TEST(PointGenerator, ASamplerMadeAsAWholeSetHasNoneAndSaysSo) {
  SamplerRequest request;
  request.n = 16, request.d = 2;
  try {
    bind_generator("poisson-disk", request);
    FAIL() << "poisson-disk gave a generator";
  } catch (const invalid_argument& e) {
    EXPECT_EQ(e.argument(), "sampler");
    EXPECT_NE(std::string(e.what()).find("whole set"), std::string::npos) << e.what();
  }
  request.randomize = "permute";  // the request is checked as generate_points checks it
  EXPECT_THROW(bind_generator("sobol", request), invalid_argument);
}

}  // namespace
}  // namespace stratum
