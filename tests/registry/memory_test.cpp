// The memory guard (stratum/memory.hpp): refusals name what is needed and
// what is available; STRATUM_MEMORY_LIMIT lowers the limit (for these tests).
#include "stratum/memory.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <string>

#include "stratum/analysis/l2_discrepancy.hpp"
#include "stratum/analysis/measures.hpp"
#include "stratum/registry.hpp"
#include "stratum/util/error.hpp"

namespace {

/// Sets STRATUM_MEMORY_LIMIT for one test.
struct MemoryLimit {
  explicit MemoryLimit(const std::string& bytes) { ::setenv("STRATUM_MEMORY_LIMIT", bytes.c_str(), 1); }
  ~MemoryLimit() { ::unsetenv("STRATUM_MEMORY_LIMIT"); }
};

std::string refusal(double bytes, const std::string& what) {
  try {
    stratum::require_memory(bytes, what);
  } catch (const stratum::memory_error& e) {
    return e.what();
  }
  return "";
}

TEST(MemoryGuard, RefusesJustAboveTheLimitNamingBothSizes) {
  const MemoryLimit limit("1048576");
  EXPECT_EQ(stratum::memory_available(), 1048576u);
  EXPECT_EQ(refusal(1048577, "a test"), "needs 1.0 MiB for a test, 1.0 MiB available");
  EXPECT_EQ(refusal(1048576, "a test"), "");
  EXPECT_EQ(refusal(1.5 * 1048576, "x"), "needs 1.5 MiB for x, 1.0 MiB available");
}

TEST(MemoryGuard, ALimitThatIsNotAByteCountIsNamed) {
  const MemoryLimit limit("12GB");
  EXPECT_THROW(stratum::memory_available(), stratum::invalid_argument);
}

TEST(MemoryGuard, WithoutALimitWhatIsAvailableIsPositive) {
  // The machine's available memory moves between two reads (other processes
  // run beside the tests), so only its sign is stable here.
  EXPECT_GT(stratum::memory_available(), 0u);
  EXPECT_GT(stratum::max_coordinates(), 0u);
}

TEST(MemoryGuard, MaxCoordinatesIsTheLimitInWholeDoubles) {
  const MemoryLimit limit("8388611");  // 8 MiB + 3 bytes: the 3 bytes are no double
  EXPECT_EQ(stratum::max_coordinates(), 8388608u / sizeof(double));
}

TEST(MemoryGuard, FormatsSizes) {
  EXPECT_EQ(stratum::format_bytes(512), "512 B");
  EXPECT_EQ(stratum::format_bytes(3.5 * 1024), "3.5 KiB");
  EXPECT_EQ(stratum::format_bytes(24.0 * 1024 * 1024 * 1024), "24.0 GiB");
}

TEST(MemoryGuard, GeneratingPointsCountsNTimesD) {
  stratum::SamplerRequest request;
  request.n = 1000;
  request.d = 8;  // 64000 bytes
  {
    const MemoryLimit limit("63999");
    try {
      stratum::generate_points("random", request);
      FAIL() << "not refused";
    } catch (const stratum::memory_error& e) {
      EXPECT_STREQ(e.what(), "needs 62.5 KiB for 1000 x 8 points of random, 62.5 KiB available");
    }
  }
  const MemoryLimit limit("64000");
  EXPECT_EQ(stratum::generate_points("random", request).n, 1000u);
}

TEST(MemoryGuard, TheL2MeasureCountsItsBuffers) {
  namespace sa = stratum::analysis;
  // The fast L2-star for d = 1: 16 bytes of sort key per point with the
  // 8-byte sorted column; the pairwise formula: two copies of the points.
  EXPECT_EQ(sa::l2_working_bytes(sa::L2Kind::star, 1000, 1), 24000);
  EXPECT_EQ(sa::l2_working_bytes(sa::L2Kind::centered, 1000, 3), 48000);
  std::vector<double> x(1000);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = (i + 0.5) / 1000;
  const sa::PointView view{x.data(), 1000, 1};
  {
    const MemoryLimit limit("23999");
    EXPECT_THROW(sa::l2_discrepancy_squared(sa::L2Kind::star, view), stratum::memory_error);
    EXPECT_THROW(sa::require_measure_memory("l2-star", 1000, 1, {}), stratum::memory_error);
  }
  const MemoryLimit limit("32000");  // 8000 bytes of points and 24000 of buffers
  EXPECT_NO_THROW(sa::require_measure_memory("l2-star", 1000, 1, {}));
  EXPECT_GT(sa::l2_discrepancy_squared(sa::L2Kind::star, view), 0);
}

TEST(MemoryGuard, TheOtherMeasuresCountTheirBuffers) {
  namespace sa = stratum::analysis;
  // Random-edge keeps one value per line: 2^32 lines are 32 GiB, refused
  // before the 16 points are generated and, for points handed in, before
  // the lines are drawn.
  const std::map<std::string, std::string> lines{{"lines", "4294967296"}};
  std::vector<double> square(32);
  for (std::size_t i = 0; i < square.size(); ++i) square[i] = (i + 0.5) / 32;
  const sa::PointView sixteen{square.data(), 16, 2};
  {
    const MemoryLimit limit("1073741824");
    EXPECT_THROW(sa::require_measure_memory("edge-random", 16, 2, {lines, 1}), stratum::memory_error);
    EXPECT_THROW(sa::compute_measure("edge-random", sixteen, {lines, 1}), stratum::memory_error);
    EXPECT_NO_THROW(sa::require_measure_memory("edge-random", 16, 2, {{{"lines", "1000"}}, 1}));
  }
  // Star bounds (10^6 points in d = 3 are past the exact method) on 2
  // workers: sorted axes 24 MB, point lists 8 MB, two stacks 8 MB, and the
  // points 24 MB.
  {
    const MemoryLimit limit("63999999");
    EXPECT_THROW(sa::require_measure_memory("star", 1000000, 3, {{}, 2}), stratum::memory_error);
  }
  {
    const MemoryLimit limit("64000000");
    EXPECT_NO_THROW(sa::require_measure_memory("star", 1000000, 3, {{}, 2}));
  }
  // The neighbour grid of min-distance: 8 bytes per point.
  {
    const MemoryLimit limit("127");
    EXPECT_THROW(sa::compute_measure("min-distance", sixteen, {}), stratum::memory_error);
  }
  const MemoryLimit limit("128");
  EXPECT_GT(sa::compute_measure("min-distance", sixteen, {}).value, 0);
}

}  // namespace
