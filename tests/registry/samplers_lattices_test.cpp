// Registry entries "fibonacci" and "lattice" (src/registry/samplers_lattices.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "stratum/randomizers/cranley_patterson.hpp"
#include "stratum/registry.hpp"
#include "stratum/sequences/lattice.hpp"
#include "stratum/util/error.hpp"

namespace stratum {
namespace {

SamplerRequest request_of(std::uint64_t n, unsigned d, std::map<std::string, std::string> params = {}) {
  SamplerRequest request;
  request.n = n;
  request.d = d;
  request.params = std::move(params);
  return request;
}

// The invalid_argument a request raises (its argument and message).
std::pair<std::string, std::string> error_of(const std::string& name, const SamplerRequest& request) {
  try {
    generate_points(name, request);
  } catch (const invalid_argument& e) {
    return {e.argument(), e.what()};
  }
  return {"(none)", ""};
}

TEST(SamplersLattices, FibonacciIsTheClassicLattice) {
  const PointSet points = generate_points("fibonacci", request_of(89, 2));
  ASSERT_EQ(points.n, 89u);
  for (std::size_t i = 0; i < 89; ++i) {
    EXPECT_EQ(points(i, 0), static_cast<double>(i) / 89);
    EXPECT_EQ(points(i, 1), static_cast<double>(i * 55 % 89) / 89);
  }
  EXPECT_EQ(find_sampler("fibonacci").randomizers, (std::vector<std::string>{"none", "cp"}));
}

TEST(SamplersLattices, CranleyPattersonShiftsEveryPointAndKeepsLatin) {
  auto request = request_of(233, 2);
  request.randomize = "cp";
  request.seed = 17;
  const PointSet shifted = generate_points("fibonacci", request);
  const CranleyPattersonRotation rotation(17);
  std::vector<int> rows(233), cols(233);
  for (std::size_t i = 0; i < 233; ++i) {
    EXPECT_EQ(shifted(i, 1), rotation(static_cast<double>(i * 144 % 233) / 233, 1));
    ++cols[static_cast<std::size_t>(shifted(i, 0) * 233)];
    ++rows[static_cast<std::size_t>(shifted(i, 1) * 233)];
  }
  for (std::size_t c = 0; c < 233; ++c) ASSERT_TRUE(rows[c] == 1 && cols[c] == 1) << c;
}

TEST(SamplersLattices, StrictFibonacciRejectsOtherN) {
  const auto [argument, message] = error_of("fibonacci", request_of(100, 2, {{"strict", "1"}}));
  EXPECT_EQ(argument, "n");
  EXPECT_NE(message.find("89 or 144"), std::string::npos) << message;
  EXPECT_NO_THROW(generate_points("fibonacci", request_of(144, 2, {{"strict", "1"}})));
  EXPECT_EQ(generate_points("fibonacci", request_of(100, 2))(1, 1), 0.61);  // golden rule: g = 61
  EXPECT_EQ(error_of("fibonacci", request_of(89, 3)).first, "d");
}

TEST(SamplersLattices, LatticeFromGeneratorOrKorobovParameter) {
  const PointSet given = generate_points("lattice", request_of(89, 2, {{"generator", "1,55"}}));
  const PointSet fibonacci = generate_points("fibonacci", request_of(89, 2));
  for (std::size_t k = 0; k < 89 * 2; ++k) EXPECT_EQ(given.data[k], fibonacci.data[k]);

  const PointSet korobov = generate_points("lattice", request_of(1021, 4, {{"a", "76"}}));
  const auto z = korobov_generator(1021, 76, 4);
  for (std::size_t i = 0; i < 1021; ++i)
    for (unsigned j = 0; j < 4; ++j) ASSERT_EQ(korobov(i, j), static_cast<double>(i * z[j] % 1021) / 1021);
}

// Without generator= or a=, the Korobov search (a = 39 for n = 1009, d = 4;
// see lattice_test.cpp), the same on 1 and 2 threads.
TEST(SamplersLattices, LatticeSearchesAKorobovParameter) {
  auto request = request_of(1009, 4);
  const PointSet one = generate_points("lattice", request);
  request.threads = 2;
  const PointSet two = generate_points("lattice", request);
  const auto z = korobov_generator(1009, KorobovSearch(1009, 4).best(), 4);
  EXPECT_EQ(z[1], 39u);
  for (std::size_t i = 0; i < 1009; ++i)
    for (unsigned j = 0; j < 4; ++j) {
      ASSERT_EQ(one(i, j), static_cast<double>(i * z[j] % 1009) / 1009);
      ASSERT_EQ(two(i, j), one(i, j));
    }
  // A smaller gamma weights later dimensions less and may pick another a.
  EXPECT_NO_THROW(generate_points("lattice", request_of(1009, 4, {{"gamma", "0.5"}})));
}

TEST(SamplersLattices, BadParametersNameTheParameter) {
  struct Case {
    SamplerRequest request;
    std::string argument, words;
  };
  const std::vector<Case> cases = {
      {request_of(89, 3, {{"generator", "1,55"}}), "generator", "has 2 entries; d = 3 needs 3"},
      {request_of(89, 2, {{"generator", "1,0"}}), "generator[1]",
       "invalid generator[1] = 0: must be an integer in [1, inf)"},
      {request_of(89, 2, {{"generator", "1,89"}}), "generator", "[1, 89)"},
      {request_of(89, 2, {{"generator", "1,-3"}}), "generator[1]", "invalid generator[1] = -3"},
      {request_of(89, 2, {{"generator", "1,x"}}), "generator[1]", "integer"},
      {request_of(89, 2, {{"generator", "1,55"}, {"a", "55"}}), "generator", "not both"},
      {request_of(89, 2, {{"a", "0"}}), "a", "invalid a = 0: must be an integer in [1, inf)"},
      {request_of(89, 2, {{"a", "89"}}), "a", "[1, 89)"},
      {request_of(100, 3, {{"a", "10"}}), "a", "coprime"},
      {request_of(89, 2, {{"gamma", "2"}}), "gamma", "(0, 1]"},
      {request_of(89, 2, {{"gamma", "abc"}}), "gamma", "(0, 1]"},
      {request_of(std::uint64_t{1} << 25, 4), "n", "2^26"},
  };
  for (const auto& c : cases) {
    const auto [argument, message] = error_of("lattice", c.request);
    EXPECT_EQ(argument, c.argument) << message;
    EXPECT_NE(message.find(c.words), std::string::npos) << message;
  }
  auto request = request_of(89, 2);
  request.start = 5;
  EXPECT_EQ(error_of("lattice", request).first, "start");  // a finite pattern
}

}  // namespace
}  // namespace stratum
