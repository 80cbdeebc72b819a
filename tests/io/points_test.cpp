#include "stratum/io/points.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "stratum/util/error.hpp"

namespace stratum {
namespace {

PointSet sample_points() {
  PointSet points;
  points.n = 3;
  points.d = 2;
  points.data.reset(new double[6]{0.1, 0.2, 1.0 / 3, 0.5, 0.999999999999, 0.0});
  return points;
}

class PointsIo : public ::testing::TestWithParam<std::string> {};

TEST_P(PointsIo, RoundTripsExactly) {
  // One directory per format: ctest runs the cases in parallel.
  const auto dir = std::filesystem::temp_directory_path() / ("stratum_io_test_" + GetParam());
  std::filesystem::create_directories(dir);
  const auto path = dir / ("points." + GetParam());
  const PointSet points = sample_points();
  io::write_points_file(path, points, io::parse_point_format(GetParam()));
  const PointSet back = io::read_points_file(path);
  ASSERT_EQ(back.n, 3u);
  ASSERT_EQ(back.d, 2u);
  for (std::size_t k = 0; k < 6; ++k) EXPECT_EQ(back.data[k], points.data[k]);
  std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Formats, PointsIo, ::testing::Values("txt", "csv", "npy"));

TEST(PointsIoErrors, UnwritableDirectoryLeavesNoFile) {
  EXPECT_THROW(io::write_points_file("/nonexistent/dir/points.txt", sample_points(), io::PointFormat::txt),
               invalid_argument);
  EXPECT_FALSE(std::filesystem::exists("/nonexistent/dir/points.txt"));
  EXPECT_THROW(io::parse_point_format("xls"), invalid_argument);
}

}  // namespace
}  // namespace stratum
