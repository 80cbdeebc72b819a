// The χ² family of tests/warps/chi2.hpp: T is computed from gtest's registry,
// and the sources cannot make more χ² checks than T counts. These tests are
// not members (their suite does not end in "Chi2"), except the one testing
// the guard against a second check, which must run inside a member suite.
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "chi2.hpp"

namespace stratum {
namespace {

namespace fs = std::filesystem;

struct SourceCensus {
  std::set<std::string> chi2_suites;           // suites named *Chi2 in TEST / TEST_F / TEST_P
  int expect_chi2_calls = 0;                   // call sites of testing::expect_chi2
  std::vector<std::string> direct_level_uses;  // files comparing against chi2_alpha() themselves
};

SourceCensus census_of_test_sources() {
  SourceCensus census;
  const std::regex suite(R"(\bTEST(_F|_P)?\(\s*(\w+Chi2)\s*,)"), call(R"(\btesting::expect_chi2\()");
  const fs::path root = fs::path(STRATUM_SOURCE_DIR) / "tests";
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    const std::string ext = entry.path().extension().string();
    if (!entry.is_regular_file() || (ext != ".cpp" && ext != ".hpp")) continue;
    if (entry.path().filename() == "chi2.hpp") continue;  // the definitions, not uses
#ifndef STRATUM_HAS_RENDER
    // tests/CMakeLists.txt leaves these out of a build without the renderer.
    const std::string area = entry.path().lexically_relative(root).begin()->string();
    if (area == "render" || area == "report") continue;
#endif
    std::ifstream in(entry.path());
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (std::sregex_iterator m(text.begin(), text.end(), suite), end; m != end; ++m)
      census.chi2_suites.insert((*m)[2]);
    census.expect_chi2_calls +=
        static_cast<int>(std::distance(std::sregex_iterator(text.begin(), text.end(), call), std::sregex_iterator()));
    if (entry.path().filename() != "chi2_family_test.cpp" && text.find("chi2_alpha()") != std::string::npos)
      census.direct_level_uses.push_back(entry.path().lexically_relative(root).string());
  }
  return census;
}

/// Registered suites named *Chi2, without a TEST_P instantiation's "Prefix/".
std::set<std::string> registered_chi2_suites() {
  std::set<std::string> names;
  const ::testing::UnitTest& unit = *::testing::UnitTest::GetInstance();
  for (int i = 0; i < unit.total_test_suite_count(); ++i) {
    const std::string name = unit.GetTestSuite(i)->name();
    if (testing::is_chi2_suite(name) && unit.GetTestSuite(i)->total_test_count() > 0)
      names.insert(name.substr(name.rfind('/') + 1));
  }
  return names;
}

// T and the per-test level, printed; and what the sources hold agrees with
// what gtest registered: every *Chi2 suite in the sources has registered tests
// (a case list filtered by a name or field that changed would leave a suite
// empty and silently drop its χ² tests), each expect_chi2 call site is at least
// one registered member, and no test compares against chi2_alpha() itself
// (which would bypass expect_chi2's guards).
TEST(WarpChi2Family, CountIsComputedFromTheRegisteredTests) {
  const int tests = testing::chi2_tests_in_suite();
  const double level = testing::chi2_alpha();
  std::cout << "χ² family: T = " << tests << " tests in *Chi2 suites, family α = 0.01, per-test level (Šidák) " << level
            << "\n";
  ::testing::Test::RecordProperty("chi2_family_tests", tests);
  const SourceCensus census = census_of_test_sources();
  EXPECT_EQ(registered_chi2_suites(), census.chi2_suites);
  EXPECT_GE(census.expect_chi2_calls, static_cast<int>(census.chi2_suites.size()));
  EXPECT_GE(tests, census.expect_chi2_calls);
  // Today's census of tests/warps: alias 2, 1D densities 6 + bilinear 1, disk 4,
  // piecewise 1D 1 and 2D 1, projected solid angle 3, sphere 5, spherical
  // rectangle 2 and triangle 3, triangle 2, the guard test below 1: 31; of
  // tests/render: the exact disk's light strategies 3, light sampling 3, the
  // glossy BSDF 4: 10 more. A lower count means χ² tests were lost.
#ifdef STRATUM_HAS_RENDER
  EXPECT_GE(tests, 41);
#else
  EXPECT_GE(tests, 31);
#endif
  for (const auto& file : census.direct_level_uses)
    ADD_FAILURE() << "tests/" << file << " uses chi2_alpha() directly: check through testing::expect_chi2";
}

TEST(WarpChi2Family, LevelIsSidakAtOnePercent) {
  const int tests = testing::chi2_tests_in_suite();
  const double level = testing::chi2_alpha();
  EXPECT_NEAR(std::pow(1 - level, tests), 0.99, 1e-14);
  EXPECT_GT(level, 0.01 / tests);  // Šidák is slightly less strict than Bonferroni
  EXPECT_LT(level, 0.01 / tests * 1.01);
}

const testing::Chi2Result passing{1.0, 10, 0.5, "a made-up result"};

TEST(WarpChi2Family, CheckOutsideAChi2SuiteFails) {
  EXPECT_NONFATAL_FAILURE(testing::expect_chi2(passing), "must live in a test suite whose name ends in \"Chi2\"");
}

// A member (it counts in T): its first check passes on a made-up p = 0.5, the
// second check in the same gtest is refused.
class WarpChi2FamilyGuardChi2 : public testing::Chi2Fixture<> {};

TEST_F(WarpChi2FamilyGuardChi2, SecondCheckInOneTestFails) {
  testing::expect_chi2(passing);
  EXPECT_NONFATAL_FAILURE(testing::expect_chi2(passing), "expect_chi2 called twice");
}

TEST(WarpChi2Family, ParamNames) {
  EXPECT_EQ(testing::chi2_param_name("cone -0.3"), "cone_m0_3");
  EXPECT_EQ(testing::chi2_param_name("hemisphere-cosine"), "hemisphere_cosine");
  EXPECT_EQ(testing::chi2_param_name("small (S ≈ 2e-4)"), "small_S_2e_4");
  EXPECT_EQ(testing::chi2_param_name("wide (Ω > 2)"), "wide_2");
}

}  // namespace
}  // namespace stratum
