/// The report's picture helpers (render_support: crops, differences, the
/// picture grid) and §5's disk maps with their strata drawn, checked
/// against what the maps are: the polar map sends the line U₂ = c to the
/// circle of radius √c and U₁ = c to the ray at angle 2πc; the concentric
/// map sends the square's boundary to the unit circle and its middle lines
/// to the disk's diameters (Shirley, Chiu 1997).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "report/render_support.hpp"
#include "section_harness.hpp"

namespace stratum::report {
namespace {

render::Image ramp(int width, int height) {
  render::Image image;
  image.width = width;
  image.height = height;
  image.samples = 4;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) {
        image.rgb.push_back(0.01 * (x + 10 * y) + c);
        image.variance.push_back(0.001 * x);
      }
  return image;
}

TEST(ReportPictures, CropsScaleWithTheImageAndKeepTheirPixels) {
  const Crop crop{0.25, 0.5, 0.25, 0.5, "test"};
  const PixelBox box = crop_pixels(crop, 8, 4);
  EXPECT_EQ(box.x, 2);
  EXPECT_EQ(box.y, 2);
  EXPECT_EQ(box.width, 2);
  EXPECT_EQ(box.height, 2);
  const PixelBox big = crop_pixels(crop, 256, 256);
  EXPECT_EQ(big.x, 64);
  EXPECT_EQ(big.width, 64);
  // A crop reaching past the border is cut at it; a tiny one keeps a pixel.
  const PixelBox edge = crop_pixels({0.9, 0.9, 0.5, 0.5, ""}, 10, 10);
  EXPECT_EQ(edge.x + edge.width, 10);
  EXPECT_EQ(crop_pixels({0, 0, 0.001, 0.001, ""}, 10, 10).width, 1);

  const render::Image image = ramp(8, 4);
  const render::Image part = crop_image(image, box);
  ASSERT_EQ(part.rgb.size(), 2u * 2 * 3);
  EXPECT_DOUBLE_EQ(part.rgb[0], image.rgb[3 * (2 * 8 + 2)]);
  EXPECT_DOUBLE_EQ(part.rgb.back(), image.rgb[3 * (3 * 8 + 3) + 2]);
  EXPECT_DOUBLE_EQ(part.variance[3], image.variance[3 * (2 * 8 + 3)]);
  const auto mask = box_mask(box, 8, 4);
  EXPECT_EQ(std::count(mask.begin(), mask.end(), true), 4);
  EXPECT_TRUE(mask[2 * 8 + 2] && mask[3 * 8 + 3] && !mask[1 * 8 + 2]);
  // The region's error is the masked MSE: here a constant offset of 0.1.
  render::Image shifted = image;
  for (double& v : shifted.rgb) v += 0.1;
  const RegionError error = region_error(shifted, image, box);
  EXPECT_NEAR(error.mse, 0.01, 1e-12);
  EXPECT_NEAR(error.sample_variance, (0.002 + 0.003) / 2 * 4, 1e-12);
}

TEST(ReportPictures, TheHeaviestWindowCoversWhereTheWeightIs) {
  // A 40×20 image, weight 1 everywhere and 5 on a 3×3 block at (30, 12):
  // the 5-pixel window (a quarter of 20) holding the most covers the block,
  // and brute force over every window agrees with the summed-area table.
  const int width = 40, height = 20;
  std::vector<double> weight(width * height, 1.0);
  for (int y = 12; y < 15; ++y)
    for (int x = 30; x < 33; ++x) weight[y * width + x] = 5;
  const Crop crop = heaviest_window(weight, width, height, 0.25, "block");
  const PixelBox box = crop_pixels(crop, width, height);
  EXPECT_EQ(box.width, 5);
  EXPECT_EQ(box.height, 5);
  EXPECT_TRUE(box.x <= 30 && box.x + box.width >= 33 && box.y <= 12 && box.y + box.height >= 15)
      << box.x << "," << box.y;
  double best = 0;
  int best_x = -1, best_y = -1;
  for (int y = 0; y + 5 <= height; ++y)
    for (int x = 0; x + 5 <= width; ++x) {
      double total = 0;
      for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 5; ++i) total += weight[(y + j) * width + x + i];
      if (total > best) best = total, best_x = x, best_y = y;
    }
  EXPECT_EQ(box.x, best_x);
  EXPECT_EQ(box.y, best_y);
  EXPECT_EQ(crop.label, "block");
}

TEST(ReportPictures, DifferencesAndTheGrid) {
  render::Image image = ramp(4, 4);
  for (double& v : image.rgb) v = 0.2;
  for (int c = 0; c < 3; ++c) image.rgb[image.rgb.size() - 1 - c] = 2;  // the last pixel brighter than white
  render::Image brighter = image;
  for (double& v : brighter.rgb) v += 0.5;
  // Luminance weights sum to 1: a grey offset of 0.5 is a luminance of 0.5.
  for (const double d : absolute_difference(brighter, image)) EXPECT_NEAR(d, 0.5, 1e-12);
  // As displayed: sRGB(0.7) − sRGB(0.2) where both are below white, nothing
  // where both are white.
  const auto srgb = [](double v) { return 1.055 * std::pow(v, 1 / 2.4) - 0.055; };
  const auto shown = displayed_difference(brighter, image);
  EXPECT_NEAR(shown.front(), srgb(0.7) - srgb(0.2), 1e-12);
  EXPECT_NEAR(shown.back(), 0, 1e-12);

  const std::vector<Crop> crops{{0, 0, 0.5, 0.5, "corner"}};
  const nlohmann::json panels = picture_grid({{&image, "base"}, {&brighter, "other"}}, crops, &image, "|difference|");
  ASSERT_EQ(panels.size(), 6u);  // two renders, two crops, a blank and a heat map
  EXPECT_EQ(panels[0]["boxes"][0], nlohmann::json::array({0, 0, 2, 2}));
  EXPECT_EQ(panels[2]["width"], 2);
  EXPECT_TRUE(panels[4]["blank"].get<bool>());
  EXPECT_EQ(panels[5]["heat"].size(), 16u);
  EXPECT_NEAR(panels[5]["scale"].get<double>(), 0.5, 1e-9);  // every difference is 0.5
}

TEST(ReportPictures, LargeLightBoxKeepsThePower) {
  const auto box = render::comparison_scene("", false, 16, 16);
  const auto large = large_light_box(16, 16);
  auto power = [](const render::Scene& scene) {
    double total = 0, side = 0;
    for (const auto& light : scene.lights) {
      if (light.type != render::LightType::area) continue;
      const auto& shape = scene.shapes[light.shape];
      const double area = length(shape.edge_u) * length(shape.edge_v);
      total += area * scene.materials[shape.material].emission.x;
      side = std::max(side, length(shape.edge_u));
    }
    return std::pair{total, side};
  };
  EXPECT_NEAR(power(large.scene).first, power(box.scene).first, 1e-9 * power(box.scene).first);
  EXPECT_DOUBLE_EQ(power(large.scene).second, 300);
  EXPECT_NE(large.key, box.key);
}

TEST(ReportPictures, DiskMapsDrawTheirStrataWhereTheMapsSendThem) {
  testing::TempFolder folder;
  std::vector<plot::PlotJob> plots;
  const Section section = testing::run_quick_section("disk-maps", folder, plots);
  ASSERT_EQ(plots.size(), 1u);
  const auto& panels = plots[0].data["panels"];
  ASSERT_EQ(panels.size(), 3u);
  const int cells = panels[0]["grid"];
  const auto& polar = panels[1];
  const auto& concentric = panels[2];
  EXPECT_NE(polar["title"].get<std::string>().find("θ = 2πU₁, r = √U₂"), std::string::npos);
  EXPECT_NE(concentric["title"].get<std::string>().find("θ = πU₂/(4U₁)"), std::string::npos);
  // Lines: first U₁ = k/cells for k = 0..cells, then U₂ = k/cells.
  ASSERT_EQ(polar["lines"].size(), 2u * (cells + 1));
  ASSERT_EQ(concentric["lines"].size(), 2u * (cells + 1));
  const double rounding = 2e-5;  // the figure data keeps 5 decimals
  for (int k = 0; k <= cells; ++k) {
    const double c = std::min(double(k) / cells, std::nextafter(1.0, 0.0));
    // Polar, U₂ = c: the circle of radius √c.
    const auto& ring = polar["lines"][cells + 1 + k];
    for (std::size_t i = 0; i < ring[0].size(); ++i)
      EXPECT_NEAR(std::hypot(ring[0][i].get<double>(), ring[1][i].get<double>()), std::sqrt(c), rounding) << k;
    // Polar, U₁ = c: the ray at angle 2πc (checked away from the centre).
    const auto& ray = polar["lines"][k];
    for (std::size_t i = 0; i < ray[0].size(); ++i) {
      const double x = ray[0][i], y = ray[1][i];
      if (std::hypot(x, y) < 0.1) continue;
      EXPECT_NEAR(x * std::sin(2 * std::numbers::pi * c) - y * std::cos(2 * std::numbers::pi * c), 0, rounding) << k;
    }
  }
  // Concentric: the square's four sides land on the unit circle, and its
  // middle lines U₁ = 1/2 and U₂ = 1/2 on the two diameters.
  for (const int line : {0, cells, cells + 1, 2 * cells + 1})
    for (std::size_t i = 0; i < concentric["lines"][line][0].size(); ++i)
      EXPECT_NEAR(
          std::hypot(concentric["lines"][line][0][i].get<double>(), concentric["lines"][line][1][i].get<double>()), 1,
          rounding)
          << line;
  const auto& vertical = concentric["lines"][cells / 2];
  const auto& horizontal = concentric["lines"][cells + 1 + cells / 2];
  for (std::size_t i = 0; i < vertical[0].size(); ++i) {
    EXPECT_NEAR(vertical[0][i].get<double>(), 0, rounding);
    EXPECT_NEAR(horizontal[1][i].get<double>(), 0, rounding);
  }
  // The formulas are on the page too.
  bool formulas = false;
  for (const auto& text : section.text) formulas |= text.find("θ = πU₂/(4U₁)") != std::string::npos;
  EXPECT_TRUE(formulas);
}

}  // namespace
}  // namespace stratum::report
