// The one parameter parser (registry/params.hpp): every type, every range
// form, the edges of the 64-bit integers and of the doubles, list lengths
// and separators, binding with defaults, and the typed accessors. The
// registry tests meet these rules through real entries; here each rule is
// checked on its own, against values worked out by hand.
#include "stratum/registry/params.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>

#include "error_of.hpp"
#include "stratum/util/error.hpp"

namespace stratum {
namespace {

using testing::error_of;

std::string parse_error(const Param& param, std::string_view text) {
  return error_of([&] { parse_param(param, text); });
}

TEST(ParamParser, IntegerWithANegativeRangeIsSigned) {
  const Param offset = params::integer("offset", "", "", closed(-5, 5));
  EXPECT_EQ(std::get<std::int64_t>(parse_param(offset, "-5")), -5);
  EXPECT_EQ(std::get<std::int64_t>(parse_param(offset, "5")), 5);
  EXPECT_EQ(parse_error(offset, "6"), "invalid offset = 6: must be an integer in [-5, 5]");
  EXPECT_EQ(parse_error(offset, "-6"), "invalid offset = -6: must be an integer in [-5, 5]");
}

TEST(ParamParser, IntegerFromZeroTakesAllOf64Bits) {
  const Param seed = params::integer("seed", "", "0", at_least(0));
  EXPECT_EQ(std::get<std::uint64_t>(parse_param(seed, "18446744073709551615")),
            std::numeric_limits<std::uint64_t>::max());
  EXPECT_EQ(std::get<std::uint64_t>(parse_param(seed, "0")), 0u);
  // 2^64 and a negative seed are refused, not wrapped to 2^64 - 1.
  EXPECT_NE(parse_error(seed, "18446744073709551616"), "");
  EXPECT_NE(parse_error(seed, "-1"), "");
}

TEST(ParamParser, RangeBoundsAreExactForLargeIntegers) {
  // 2^53 + 1 is not a double; compared in long double it is still outside [0, 2^53].
  const Param count = params::integer("count", "", "", closed(0, 0x1p53));
  EXPECT_EQ(std::get<std::uint64_t>(parse_param(count, "9007199254740992")), 9007199254740992u);
  EXPECT_NE(parse_error(count, "9007199254740993"), "");
}

TEST(ParamParser, IntegerTextIsWholeAndDecimal) {
  const Param n = params::integer("n", "", "", closed(1, 100));
  for (const char* bad : {"", " 5", "5 ", "5.0", "5e0", "0x10", "+5", "five", "1,2"})
    EXPECT_NE(parse_error(n, bad), "") << "'" << bad << "' was accepted";
  EXPECT_EQ(parse_error(n, ""), "invalid n = '': must be an integer in [1, 100]");
}

TEST(ParamParser, RealRangesOpenAndClosed) {
  const Param unit = params::real("u", "", "", half_open(0, 1));
  EXPECT_EQ(std::get<double>(parse_param(unit, "0")), 0.0);
  EXPECT_EQ(std::get<double>(parse_param(unit, "0.999")), 0.999);
  EXPECT_EQ(parse_error(unit, "1"), "invalid u = 1: must be a finite real in [0, 1)");
  const Param positive = params::real("radius", "", "", above(0));
  EXPECT_EQ(parse_error(positive, "0"), "invalid radius = 0: must be a finite real in (0, inf)");
  EXPECT_EQ(std::get<double>(parse_param(positive, "1e-300")), 1e-300);
  const Param gap = params::real("gap", "", "", left_open(0, 2));
  EXPECT_EQ(std::get<double>(parse_param(gap, "2")), 2.0);
  EXPECT_NE(parse_error(gap, "0"), "");
}

TEST(ParamParser, RealsThatDoNotSurviveReadingAreRefused) {
  const Param any = params::real("x", "", "", any_real());
  // Overflow to inf, underflow to a subnormal or 0, and the non-finite words.
  for (const char* bad :
       {"1e999", "-1e999", "1e-320", "-1e-320", "1e-400", "inf", "-inf", "nan", "infinity", "0x1p3", "1.5.2", "1e"})
    EXPECT_NE(parse_error(any, bad), "") << "'" << bad << "' was accepted";
  EXPECT_EQ(parse_error(any, "1e-320"),
            "invalid x = 1e-320: is below the smallest normal double, 2.2e-308, so it would not read back as written: "
            "give 0 or a larger value");
  EXPECT_EQ(parse_error(params::reals("w", "", "", any_real()), "1,1e-400").substr(0, 23), "invalid w[1] = 1e-400: ");
  EXPECT_EQ(std::get<double>(parse_param(any, "-2.5e-3")), -2.5e-3);
  EXPECT_EQ(std::get<double>(parse_param(any, "1.7976931348623157e308")), std::numeric_limits<double>::max());
}

TEST(ParamParser, ListsCheckEachElementAndTheCount) {
  const Param generator = params::integers("generator", "", "", at_least(1), Length{2, 3});
  EXPECT_EQ(std::get<std::vector<std::int64_t>>(parse_param(generator, "1,55,133")),
            (std::vector<std::int64_t>{1, 55, 133}));
  EXPECT_EQ(parse_error(generator, "1,0"),
            "invalid generator[1] = 0: must be an integer in [1, inf) (generator takes 2 to 3 integers)");
  EXPECT_EQ(parse_error(generator, "1"),
            "invalid generator = (1 value): must be 2 to 3 integers in [1, inf), separated by ','");
  EXPECT_EQ(parse_error(generator, "1,2,3,4"),
            "invalid generator = (4 values): must be 2 to 3 integers in [1, inf), separated by ','");
  EXPECT_NE(parse_error(generator, "1,,2"), "");  // an empty element
  EXPECT_NE(parse_error(generator, "1,2,"), "");
  const Param weights = params::reals("weights", "", "", open(0, 1));
  EXPECT_EQ(std::get<std::vector<double>>(parse_param(weights, "0.75,0.5")), (std::vector<double>{0.75, 0.5}));
  EXPECT_EQ(parse_error(weights, "0.5,1e999"),
            "invalid weights[1] = 1e999: must be a finite real in (0, 1) (weights takes 1 or more reals)");
}

TEST(ParamParser, AListWithItsOwnSeparatorTakesCommasToo) {
  const Param strata = params::integers("strata", "", "", at_least(1), Length{2, 2}, 'x');
  EXPECT_EQ(std::get<std::vector<std::int64_t>>(parse_param(strata, "4x8")), (std::vector<std::int64_t>{4, 8}));
  EXPECT_EQ(std::get<std::vector<std::int64_t>>(parse_param(strata, "4,8")), (std::vector<std::int64_t>{4, 8}));
  EXPECT_EQ(allowed_values(strata), "must be 2 integers in [1, inf), separated by 'x' or ','");
}

TEST(ParamParser, ChoicesAndFlags) {
  const Param colour = params::choice("colour", "", "gray", {"gray", "natural"});
  EXPECT_EQ(std::get<std::string>(parse_param(colour, "natural")), "natural");
  EXPECT_EQ(parse_error(colour, "Gray"), "invalid colour = Gray: must be one of gray, natural");
  const Param periodic = params::flag("periodic", "", "0");
  for (const char* yes : {"1", "true", "YES", "On"}) EXPECT_TRUE(std::get<bool>(parse_param(periodic, yes))) << yes;
  for (const char* no : {"0", "False", "no", "OFF"}) EXPECT_FALSE(std::get<bool>(parse_param(periodic, no))) << no;
  EXPECT_EQ(parse_error(periodic, "2"), "invalid periodic = 2: must be a flag: 1/0, true/false, yes/no or on/off");
}

TEST(ParamParser, RangeTextNamesPowersOfTwo) {
  EXPECT_EQ(range_text(closed(1, 0x1p40)), "[1, 2^40]");
  EXPECT_EQ(range_text(half_open(0, 0x1p64)), "[0, 2^64)");
  EXPECT_EQ(range_text(any_real()), "");
  EXPECT_EQ(range_text(at_least(-1)), "[-1, inf)");
}

TEST(ParamChecker, TypedNumbersMeetTheSameRules) {
  const Param n = params::integer("n", "", "", closed(1, 10));
  EXPECT_NO_THROW(check_param(n, {3}));
  EXPECT_EQ(error_of([&] { check_param(n, {2.5}); }), "invalid n = 2.5: must be an integer in [1, 10]");
  EXPECT_EQ(error_of([&] { check_param(n, {11}); }), "invalid n = 11: must be an integer in [1, 10]");
  EXPECT_EQ(error_of([&] { check_param(n, {1, 2}); }), "invalid n = (2 values): must be an integer in [1, 10]");
  const Param sizes = params::reals("sizes", "", "", above(0), Length{1, 2});
  EXPECT_EQ(error_of([&] {
              check_param(sizes, {1, std::numeric_limits<double>::quiet_NaN()});
            }),
            "invalid sizes[1] = nan: must be a finite real in (0, inf) (sizes takes 1 to 2 reals)");
  EXPECT_THROW(check_param(params::text("name", "", ""), {1}), std::logic_error);
}

TEST(ParamBinding, DefaultsFillInAndUnknownKeysNameTheOption) {
  const std::vector<Param> schema{params::integer("candidates", "", "30", closed(1, 1000)),
                                  params::flag("periodic", "", "0"), params::real("radius", "", "", above(0))};
  const ParamValues bound = bind_params("poisson-disk", schema, {{"periodic", "yes"}});
  EXPECT_EQ(bound.integer("candidates"), 30);
  EXPECT_TRUE(bound.flag("periodic"));
  EXPECT_FALSE(bound.has("radius"));  // no default: the entry computes it
  EXPECT_EQ(error_of([&] {
              bind_params("poisson-disk", schema, {{"lines", "5"}}, "measure-param");
            }),
            "invalid measure-param = lines=5: poisson-disk takes candidates, periodic, radius");
  EXPECT_EQ(error_of([&] {
              bind_params("random", {}, {{"x", "1"}});
            }),
            "invalid param = x=1: random takes no parameters");
  EXPECT_EQ(error_of([&] {
              bind_params("poisson-disk", schema, {{"candidates", "0"}});
            }),
            "invalid candidates = 0: must be an integer in [1, 1000]");
}

TEST(ParamBinding, AccessorsRefuseNamesAndTypesOutsideTheSchema) {
  const std::vector<Param> schema{params::integer("seed", "", "18446744073709551615", at_least(0)),
                                  params::integer("shift", "", "-3", closed(-10, 10)),
                                  params::reals("weights", "", "0.5", open(0, 1))};
  const ParamValues bound = bind_params("test", schema, {});
  EXPECT_EQ(bound.unsigned_integer("seed"), std::numeric_limits<std::uint64_t>::max());
  EXPECT_THROW(bound.integer("seed"), std::logic_error);  // beyond int64
  EXPECT_EQ(bound.integer("shift"), -3);
  EXPECT_THROW(bound.unsigned_integer("shift"), std::logic_error);  // may be negative
  EXPECT_EQ(bound.real("shift"), -3.0);
  EXPECT_EQ(bound.reals("weights"), std::vector<double>{0.5});
  EXPECT_THROW(bound.integers("weights"), std::logic_error);
  EXPECT_THROW(bound.real("missing"), std::logic_error);
}

TEST(ParamValuesAsReals, EveryNumericFormAndNothingElse) {
  EXPECT_EQ(as_reals(ParamValue{std::int64_t{-2}}), std::vector<double>{-2});
  EXPECT_EQ(as_reals(ParamValue{std::uint64_t{7}}), std::vector<double>{7});
  EXPECT_EQ(as_reals(ParamValue{std::vector<std::int64_t>{1, 2}}), (std::vector<double>{1, 2}));
  EXPECT_THROW(as_reals(ParamValue{std::string("x")}), std::logic_error);
  EXPECT_THROW(as_reals(ParamValue{true}), std::logic_error);
}

}  // namespace
}  // namespace stratum
