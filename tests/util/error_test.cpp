#include "stratum/util/error.hpp"

#include <gtest/gtest.h>

#include "stratum/util/real.hpp"

namespace stratum {
namespace {

TEST(Error, MessageNamesArgumentValueAndAllowed) {
  try {
    require(false, "radius", 1.5, "must be in (0, 1]");
    FAIL();
  } catch (const invalid_argument& e) {
    EXPECT_EQ(e.argument(), "radius");
    EXPECT_STREQ(e.what(), "invalid radius = 1.5: must be in (0, 1]");
  }
  EXPECT_NO_THROW(require(true, "n", 3, "anything"));
}

TEST(Real, FloatConversionNeverReachesOne) {
  EXPECT_LT(to_unit_float(one_minus_epsilon_double), 1.0f);
  EXPECT_EQ(to_unit<double>(0.25), 0.25);
  EXPECT_EQ(to_unit<float>(0.25), 0.25f);
}

}  // namespace
}  // namespace stratum
