// The pixel sampler's set techniques (pixel/set_techniques.hpp) against the
// registry: for every sampler × randomizer the core offers, point i of the
// set of seed s is row i of generate_points(name, {n, d = 2, s, start}), bit
// for bit, for several n, seeds and starts (starts only where the technique
// is progressive); a count the technique refuses the registry refuses too.
#include "stratum/pixel/set_techniques.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <set>
#include <string>

#include "stratum/registry.hpp"

namespace {

using namespace stratum;
using namespace stratum::pixel;

template <class Technique>
void expect_registry_sets(const Technique& technique, const std::string& name, const std::string& randomizer,
                          std::map<std::string, std::string> params = {}) {
  SCOPED_TRACE(name + ":" + randomizer);
  int compared = 0;
  for (const std::uint64_t n : {1u, 4u, 7u, 16u, 64u, 100u}) {
    for (const std::uint64_t seed : {0ull, 1ull, 0x9e3779b97f4a7c15ull}) {
      for (const std::uint64_t start : {0ull, 5ull, 1000003ull}) {
        if (start != 0 && !Technique::progressive) continue;
        SamplerRequest request;
        request.n = n, request.d = 2, request.seed = seed, request.start = start, request.randomize = randomizer;
        request.params = params;
        if (!technique.takes(n)) {
          EXPECT_THROW(generate_points(name, request), invalid_argument) << " n = " << n;
          continue;
        }
        const PointSet set = generate_points(name, request);
        const typename Technique::Shape shape = technique.shape(n);
        const typename Technique::Key key = technique.key(shape, seed);
        for (std::uint64_t i = 0; i < n; ++i) {
          const Point2 both = technique.template point<2>(key, shape, start + i);
          const Point2 first = technique.template point<1>(key, shape, start + i);
          ASSERT_EQ(both[0], set(i, 0)) << "n " << n << " seed " << seed << " start " << start << " i " << i;
          ASSERT_EQ(both[1], set(i, 1)) << "n " << n << " seed " << seed << " start " << start << " i " << i;
          ASSERT_EQ(first[0], both[0]);
          ASSERT_EQ(first[1], 0.0);
        }
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 10);
}

TEST(SetTechniques, RandomJitteredPmj02AndCmjAreTheRegistrysSets) {
  expect_registry_sets(RandomTechnique{}, "random", "none");
  expect_registry_sets(JitteredTechnique{}, "jittered", "none");
  expect_registry_sets(Pmj02Technique{}, "pmj02", "none");
  expect_registry_sets(CmjTechnique{}, "cmj", "none");
  expect_registry_sets(CmjTechnique{2.0}, "cmj", "none", {{"aspect", "2"}});
}

TEST(SetTechniques, SobolAndZeroTwoUnderEveryBase2RandomizerAreTheRegistrysSets) {
  for (const char* name : {"sobol", "zero-two"}) {
    expect_registry_sets(SobolTechnique<base2_scrambles::None>{}, name, "none");
    expect_registry_sets(SobolTechnique<base2_scrambles::OwenHash>{}, name, "owen-hash");
    expect_registry_sets(SobolTechnique<base2_scrambles::Owen>{}, name, "owen");
    expect_registry_sets(SobolTechnique<base2_scrambles::Xor>{}, name, "xor");
    expect_registry_sets(SobolTechnique<base2_scrambles::Lms>{}, name, "lms");
    expect_registry_sets(SobolTechnique<base2_scrambles::Rotation>{}, name, "cp");
  }
}

TEST(SetTechniques, RotatedSequencesAreTheRegistrysSets) {
  for (const bool rotate : {false, true}) {
    const std::string randomizer = rotate ? "cp" : "none";
    expect_registry_sets(HaltonTechnique{{}, rotate}, "halton", randomizer);
    expect_registry_sets(KroneckerTechnique{Kronecker2D::of(Kronecker(2)), rotate}, "kronecker", randomizer);
    expect_registry_sets(
        KroneckerTechnique{Kronecker2D::of(Kronecker(std::vector<double>{0.25, 0.6180339887}, 0.5)), rotate},
        "kronecker", randomizer, {{"alpha", "0.25,0.6180339887"}, {"offset", "0.5"}});
    expect_registry_sets(LatticeSequenceTechnique{{}, rotate}, "lattice-sequence", randomizer);
    expect_registry_sets(LatticeSequenceTechnique{{{{1, 182667}}}, rotate}, "lattice-sequence", randomizer,
                         {{"generator", "1,182667"}});
  }
}

}  // namespace
