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

TEST(Error, PrintableEscapesControlBytesAndInvalidUtf8) {
  EXPECT_EQ(printable("plain text"), "plain text");
  EXPECT_EQ(printable("a\tb\r\n"), "a\\tb\\r\\n");
  EXPECT_EQ(printable("\x01\x7f\xff\x80z"), "\\x01\\x7f\\xff\\x80z");
  EXPECT_EQ(printable("caf\xc3\xa9 \xe2\x88\x9a \xf0\x9f\x98\x80"),
            "caf\xc3\xa9 \xe2\x88\x9a \xf0\x9f\x98\x80");            // kept
  EXPECT_EQ(printable("\xc0\xaf"), "\\xc0\\xaf");                    // an overlong '/'
  EXPECT_EQ(printable("\xed\xa0\x80"), "\\xed\\xa0\\x80");           // a surrogate
  EXPECT_EQ(printable("\xe2\x82"), "\\xe2\\x82");                    // cut short
  EXPECT_EQ(printable("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80");  // above U+10FFFF
  // The value of every message goes through it.
  EXPECT_STREQ(invalid_argument("input",
                                "a\x01"
                                "b",
                                "why")
                   .what(),
               "invalid input = a\\x01b: why");
}

TEST(Real, FloatConversionNeverReachesOne) {
  EXPECT_LT(to_unit_float(one_minus_epsilon_double), 1.0f);
  EXPECT_EQ(to_unit<double>(0.25), 0.25);
  EXPECT_EQ(to_unit<float>(0.25), 0.25f);
}

}  // namespace
}  // namespace stratum
