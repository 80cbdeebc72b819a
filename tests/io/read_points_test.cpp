#include "stratum/io/read_points.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

#include "stratum/io/points.hpp"
#include "stratum/util/error.hpp"

namespace stratum {
namespace {

/// A private directory per test: ctest runs test cases in parallel.
std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("stratum_read_points_" + name);
  std::filesystem::create_directories(dir);
  return dir;
}

std::string error_reading(const std::filesystem::path& path) {
  try {
    io::read_points_strict(path);
  } catch (const invalid_argument& error) {
    return error.what();
  }
  return "(no error)";
}

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

TEST(ReadPointsStrict, ReadsWhatStratumWritesInEveryFormat) {
  const auto dir = scratch("round_trip");
  PointSet points;
  points.n = 3;
  points.d = 2;
  points.data.reset(new double[6]{0.1, 0.2, 1.0 / 3, 0.5, 0.999999999999, 0.0});
  for (const std::string format : {"txt", "csv", "npy"}) {
    const auto path = dir / ("points." + format);
    io::write_points_file(path, points, io::parse_point_format(format));
    const PointSet back = io::read_points_strict(path);
    ASSERT_EQ(back.n, 3u) << format;
    ASSERT_EQ(back.d, 2u) << format;
    for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(back.data[i], points.data[i]) << format;
  }
  std::filesystem::remove_all(dir);
}

TEST(ReadPointsStrict, SkipsCommentsAndBlankLinesAndAcceptsCrlf) {
  const auto dir = scratch("comments");
  write_text(dir / "p.txt", "# x y\n\n0.25 0.5\r\n  0.75\t1\n");
  const PointSet points = io::read_points_strict(dir / "p.txt");
  EXPECT_EQ(points.n, 2u);
  EXPECT_EQ(points.d, 2u);
  EXPECT_EQ(points(1, 1), 1.0);
  std::filesystem::remove_all(dir);
}

// Found by fuzz_points (docs/fuzzing.md): a line of a vertical tab or form
// feed was not blank to the reader but held no field, so it became a point
// of 0 values (d = 0), and a later line reset d, leaving the set's last
// coordinates uninitialized.
TEST(ReadPointsStrict, AWhitespaceOnlyLineIsBlank) {
  const auto dir = scratch("whitespace_lines");
  write_text(dir / "p.txt", "\v\n0.5 0.25\n\f \t\n0.25 0.75\n");
  const PointSet points = io::read_points_strict(dir / "p.txt");
  EXPECT_EQ(points.n, 2u);
  EXPECT_EQ(points.d, 2u);
  EXPECT_EQ(points(0, 0), 0.5);
  EXPECT_EQ(points(1, 1), 0.75);
  write_text(dir / "only.txt", "#1$#4.\n\v");
  EXPECT_NE(error_reading(dir / "only.txt").find("holds no points"), std::string::npos)
      << error_reading(dir / "only.txt");
  std::filesystem::remove_all(dir);
}

TEST(ReadPointsStrict, NamesTheLineOrRowAndColumnAtFault) {
  const auto dir = scratch("errors");
  const std::pair<std::string, std::string> cases[] = {
      {"ragged.txt", "0.1 0.2\n0.3\n"},     {"word.txt", "0.1 0.2\n0.3 x1\n"}, {"nan.txt", "0.1 nan\n"},
      {"inf.csv", "0.1,0.2\n-inf,0.3\n"},   {"hole.csv", "0.1,,0.2\n"},        {"empty.txt", ""},
      {"blank.txt", "\n# only a comment\n"}};
  const std::string expected[] = {"line 2 has 1 values, line 1 (the first point) has 2",
                                  "line 2, column 2 is 'x1': not a number",
                                  "line 1, column 2 is 'nan': coordinates must be finite",
                                  "line 2, column 1 is '-inf'",
                                  "line 1, column 2 is '': not a number",
                                  "holds no points",
                                  "holds no points"};
  for (std::size_t c = 0; c < std::size(cases); ++c) {
    write_text(dir / cases[c].first, cases[c].second);
    const std::string message = error_reading(dir / cases[c].first);
    EXPECT_NE(message.find("invalid input = "), std::string::npos) << message;
    EXPECT_NE(message.find(expected[c]), std::string::npos) << cases[c].first << ": " << message;
  }
  EXPECT_NE(error_reading(dir / "missing.txt").find("cannot be opened"), std::string::npos);
  EXPECT_NE(error_reading(dir).find("is a directory"), std::string::npos);
  write_text(dir / "fake.npy", "hello, world");
  EXPECT_NE(error_reading(dir / "fake.npy").find("not a .npy file"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(ReadPointsStrict, RejectsNonFiniteAndTruncatedNpy) {
  const auto dir = scratch("npy");
  PointSet points;
  points.n = 2;
  points.d = 2;
  points.data.reset(new double[4]{0.1, 0.2, 0.3, std::numeric_limits<double>::quiet_NaN()});
  io::write_points_file(dir / "nan.npy", points, io::PointFormat::npy);
  EXPECT_NE(error_reading(dir / "nan.npy").find("point[1][1] is nan"), std::string::npos)
      << error_reading(dir / "nan.npy");
  points.data[3] = 0.4;
  io::write_points_file(dir / "ok.npy", points, io::PointFormat::npy);
  std::filesystem::resize_file(dir / "ok.npy", std::filesystem::file_size(dir / "ok.npy") - 8);
  EXPECT_NE(error_reading(dir / "ok.npy").find("data bytes"), std::string::npos) << error_reading(dir / "ok.npy");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace stratum
