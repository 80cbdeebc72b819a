// The registry entries of the space-time patterns (src/registry/samplers_spacetime.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "error_of.hpp"
#include "stratum/registry.hpp"
#include "stratum/spacetime/cook_pattern.hpp"
#include "stratum/spacetime/magic_square.hpp"
#include "stratum/util/error.hpp"

namespace stratum {
namespace {

SamplerRequest request_of(std::uint64_t n) {
  SamplerRequest request;
  request.n = n;
  request.d = 3;
  request.seed = 8;
  return request;
}

std::string error_of(const std::string& name, std::uint64_t n) { return testing::error_of(name, request_of(n)); }

// Point i = (row, column) lies in its stratum and in the slot the table gives.
void expect_in_slots(const PointSet& points, const SlotTable& table) {
  const std::uint32_t m = table.order;
  ASSERT_EQ(points.n, std::size_t{m} * m);
  for (std::size_t i = 0; i < points.n; ++i) {
    EXPECT_EQ(std::floor(points(i, 0) * m), i % m);
    EXPECT_EQ(std::floor(points(i, 1) * m), i / m);
    EXPECT_EQ(std::floor(points(i, 2) * m * m), table(static_cast<std::uint32_t>(i / m), i % m));
  }
}

TEST(SpaceTimeRegistry, PointsFollowTheTables) {
  expect_in_slots(generate_points("spacetime-magic", request_of(16)), pandiagonal_magic_square(4));
  expect_in_slots(generate_points("spacetime-magic", request_of(81)), pandiagonal_magic_square(9));
  expect_in_slots(generate_points("spacetime-cook", request_of(16)), cook_slots(4));
  expect_in_slots(generate_points("spacetime-cook", request_of(36)), cook_slots(6));
  expect_in_slots(generate_points("spacetime-random", request_of(25)), random_slots(5, 8));
}

TEST(SpaceTimeRegistry, CountsMustBeSquaresAndMagicOrdersValid) {
  for (const char* name : {"spacetime-random", "spacetime-cook", "spacetime-magic"}) {
    const std::string message = error_of(name, 15);
    EXPECT_NE(message.find("invalid n = 15"), std::string::npos) << message;
    EXPECT_NE(message.find("m^2"), std::string::npos) << message;
  }
  const std::string message = error_of("spacetime-magic", 36);
  EXPECT_NE(message.find("invalid n = 36"), std::string::npos) << message;
  EXPECT_NE(message.find("m mod 4 != 2"), std::string::npos) << message;
  EXPECT_NE(error_of("spacetime-magic", 9), "");
  EXPECT_EQ(error_of("spacetime-magic", 144), "");
  EXPECT_EQ(error_of("spacetime-cook", 9), "");
  auto two_d = request_of(16);
  two_d.d = 2;
  EXPECT_THROW(generate_points("spacetime-magic", two_d), invalid_argument);
}

}  // namespace
}  // namespace stratum
