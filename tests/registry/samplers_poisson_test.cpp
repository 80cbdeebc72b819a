// The registry entries "poisson-disk" and "best-candidate" (src/registry/samplers_poisson.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "error_of.hpp"
#include "stratum/patterns/best_candidate.hpp"
#include "stratum/patterns/poisson_disk.hpp"
#include "stratum/registry.hpp"
#include "stratum/util/error.hpp"

namespace stratum {
namespace {

using testing::error_of;

SamplerRequest request_of(std::optional<std::uint64_t> n, unsigned d, std::optional<double> radius = std::nullopt) {
  SamplerRequest request;
  request.n = n;
  request.d = d;
  request.seed = 3;
  request.radius = radius;
  return request;
}

double min_distance(const PointSet& points) {
  double best = 1e300;
  for (std::size_t a = 0; a < points.n; ++a)
    for (std::size_t b = a + 1; b < points.n; ++b) {
      double sum = 0;
      for (std::size_t j = 0; j < points.d; ++j) sum += std::pow(points(a, j) - points(b, j), 2);
      best = std::min(best, sum);
    }
  return std::sqrt(best);
}

TEST(PoissonRegistry, RadiusAloneGivesTheMaximalSet) {
  const PointSet points = generate_points("poisson-disk", request_of(std::nullopt, 2, 0.05));
  const auto expected = PoissonDisk(2, 0.05, 3).maximal_set();
  ASSERT_EQ(points.n * 2, expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) ASSERT_EQ(points.data[k], expected[k]);
  EXPECT_GE(min_distance(points), 0.05);
}

TEST(PoissonRegistry, CountModes) {
  const PointSet exact = generate_points("poisson-disk", request_of(500, 3));
  EXPECT_EQ(exact.n, 500u);
  const PointSet both = generate_points("poisson-disk", request_of(200, 2, 0.05));
  EXPECT_EQ(both.n, 200u);
  EXPECT_GE(min_distance(both), 0.05);
  auto periodic = request_of(64, 2);
  periodic.params["periodic"] = "1";
  periodic.params["candidates"] = "5";
  EXPECT_EQ(generate_points("poisson-disk", periodic).n, 64u);
}

TEST(PoissonRegistry, ErrorsNameTheProblem) {
  // More points than any set at this radius can hold.
  EXPECT_NE(error_of("poisson-disk", request_of(100000, 2, 0.05)).find("packing bound"), std::string::npos);
  // More than this maximal set holds (but not more than the packing bound).
  const std::string fewer = error_of("poisson-disk", request_of(600, 2, 0.05));
  EXPECT_NE(fewer.find("invalid n = 600"), std::string::npos) << fewer;
  EXPECT_NE(fewer.find("maximal Poisson-disk set"), std::string::npos) << fewer;
  // A radius whose maximal set would not fit in memory, refused up front.
  EXPECT_NE(error_of("poisson-disk", request_of(std::nullopt, 4, 1e-4)).find("MiB"), std::string::npos);
  EXPECT_NE(error_of("poisson-disk", request_of(std::nullopt, 2, 0.0)).find("radius"), std::string::npos);
  EXPECT_NE(error_of("poisson-disk", request_of(10, 5)).find("d = 5"), std::string::npos);
  auto bad = request_of(10, 2);
  bad.params["candidates"] = "0";
  EXPECT_NE(error_of("poisson-disk", bad).find("candidates"), std::string::npos);
  EXPECT_NE(error_of("poisson-disk", request_of(std::nullopt, 2)).find("radius"), std::string::npos);
}

TEST(BestCandidateRegistry, MatchesTheHeaderAndCapsTheWork) {
  const PointSet points = generate_points("best-candidate", request_of(300, 2));
  const auto expected = BestCandidate(2, 3).generate(300);
  for (std::size_t k = 0; k < expected.size(); ++k) ASSERT_EQ(points.data[k], expected[k]);
  const std::string message = error_of("best-candidate", request_of(10000, 2));
  EXPECT_NE(message.find("n must be at most 5181"), std::string::npos) << message;
  const SamplerInfo& info = find_sampler("best-candidate");
  EXPECT_NO_THROW(validate_request(info, request_of(5181, 2)));
  EXPECT_THROW(validate_request(info, request_of(5182, 2)), invalid_argument);
  auto cheap = request_of(10000, 2);
  cheap.params["candidates"] = "2";
  EXPECT_NO_THROW(validate_request(info, cheap));
  EXPECT_NO_THROW(validate_request(info, request_of(1295, 4)));
  const std::string four = error_of("best-candidate", request_of(1296, 4));
  EXPECT_NE(four.find("at most 1295"), std::string::npos) << four;
  auto euclidean = request_of(50, 3);
  euclidean.params["periodic"] = "0";
  const PointSet flat = generate_points("best-candidate", euclidean);
  const auto flat_expected = BestCandidate(3, 3, 10, false).generate(50);
  for (std::size_t k = 0; k < flat_expected.size(); ++k) ASSERT_EQ(flat.data[k], flat_expected[k]);
}

}  // namespace
}  // namespace stratum
