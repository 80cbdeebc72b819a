#include "render_support.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "sections.hpp"
#include "stratum/util/error.hpp"

namespace stratum::report {

RenderScale render_scale(const SectionContext& context) {
  return context.quick() ? RenderScale{32, 32, 64} : RenderScale{96, 96, 1024};
}

RenderScale picture_scale(const SectionContext& context) {
  return context.quick() ? RenderScale{32, 32, 64, 64} : RenderScale{256, 256, 256, 64};
}

render::ComparisonScene large_light_box(int width, int height) {
  render::ComparisonScene box = render::comparison_scene("", false, width, height);
  render::Scene& scene = box.scene;
  constexpr double side = 300;
  for (render::Shape& shape : scene.shapes) {
    render::Material& material = scene.materials.at(shape.material);
    if (shape.type != render::ShapeType::quad || material.emission.x <= 0) continue;
    const render::Vec3 centre = shape.corner + 0.5 * shape.edge_u + 0.5 * shape.edge_v;
    const double area = length(shape.edge_u) * length(shape.edge_v);
    shape.edge_u = (side / length(shape.edge_u)) * shape.edge_u;
    shape.edge_v = (side / length(shape.edge_v)) * shape.edge_v;
    shape.corner = centre - 0.5 * shape.edge_u - 0.5 * shape.edge_v;
    material.emission = (area / (side * side)) * material.emission;
  }
  scene.name = "cornell-box-large-light";
  render::validate_scene(scene);
  box.key = render::scene_fingerprint(scene);
  return box;
}

PixelBox crop_pixels(const Crop& crop, int width, int height) {
  PixelBox box;
  box.x = std::clamp(int(std::lround(crop.x * width)), 0, width - 1);
  box.y = std::clamp(int(std::lround(crop.y * height)), 0, height - 1);
  box.width = std::clamp(int(std::lround(crop.width * width)), 1, width - box.x);
  box.height = std::clamp(int(std::lround(crop.height * height)), 1, height - box.y);
  return box;
}

render::Image crop_image(const render::Image& image, const PixelBox& box) {
  render::Image crop;
  crop.width = box.width;
  crop.height = box.height;
  crop.samples = image.samples;
  crop.seconds = image.seconds;
  for (int y = box.y; y < box.y + box.height; ++y)
    for (int x = box.x; x < box.x + box.width; ++x) {
      const std::size_t p = 3 * (std::size_t(y) * image.width + x);
      crop.rgb.insert(crop.rgb.end(), image.rgb.begin() + p, image.rgb.begin() + p + 3);
      if (!image.variance.empty())
        crop.variance.insert(crop.variance.end(), image.variance.begin() + p, image.variance.begin() + p + 3);
    }
  return crop;
}

std::vector<double> absolute_difference(const render::Image& image, const render::Image& other) {
  std::vector<double> difference = render::luminance_error(image, other);
  for (double& d : difference) d = std::fabs(d);
  return difference;
}

std::vector<double> displayed_difference(const render::Image& image, const render::Image& other) {
  const auto shown = [](const render::Image& source) {
    render::Image out = source;
    for (double& v : out.rgb) {
      const double c = std::clamp(std::isfinite(v) ? v : 0.0, 0.0, 1.0);
      v = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055;
    }
    return out;
  };
  return absolute_difference(shown(image), shown(other));
}

Crop heaviest_window(const std::vector<double>& weight, int width, int height, double fraction,
                     const std::string& label) {
  const int side = std::max(1, int(std::lround(fraction * std::min(width, height))));
  // Summed-area table: sum at (x, y) = the weights above and left of pixel (x, y).
  const std::size_t stride = std::size_t(width) + 1;
  std::vector<double> sum(stride * (height + 1), 0.0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      sum[(y + 1) * stride + x + 1] = weight[std::size_t(y) * width + x] + sum[y * stride + x + 1] +
                                      sum[(y + 1) * stride + x] - sum[y * stride + x];
  const auto at = [&](int x, int y) { return sum[y * stride + x]; };
  double best = -1;
  int best_x = 0, best_y = 0;
  for (int y = 0; y + side <= height; ++y)
    for (int x = 0; x + side <= width; ++x) {
      const double total = at(x + side, y + side) + at(x, y) - at(x + side, y) - at(x, y + side);
      if (total > best) best = total, best_x = x, best_y = y;
    }
  return {double(best_x) / width, double(best_y) / height, double(side) / width, double(side) / height, label};
}

std::vector<bool> box_mask(const PixelBox& box, int width, int height) {
  std::vector<bool> mask(std::size_t(width) * height, false);
  for (int y = box.y; y < box.y + box.height; ++y)
    for (int x = box.x; x < box.x + box.width; ++x) mask[std::size_t(y) * width + x] = true;
  return mask;
}

namespace {

/// The q-quantile of all values (0 for none).
double quantile(std::vector<double> values, double q) {
  if (values.empty()) return 0;
  const auto at = values.begin() + std::ptrdiff_t(q * double(values.size() - 1));
  std::nth_element(values.begin(), at, values.end());
  return *at;
}

nlohmann::json rounded(const std::vector<double>& values) {
  nlohmann::json out = nlohmann::json::array();
  for (const double v : values) out.push_back(std::isfinite(v) ? std::round(v * 1e5) / 1e5 : 0.0);
  return out;
}

}  // namespace

nlohmann::json picture_grid(const std::vector<GridColumn>& columns, const std::vector<Crop>& crops,
                            const render::Image* baseline, const std::string& difference_title, bool displayed) {
  nlohmann::json panels = nlohmann::json::array();
  for (const GridColumn& column : columns) {
    nlohmann::json panel = image_panel(*column.image, column.title);
    nlohmann::json boxes = nlohmann::json::array();
    for (const Crop& crop : crops) {
      const PixelBox box = crop_pixels(crop, column.image->width, column.image->height);
      boxes.push_back({box.x, box.y, box.width, box.height});
    }
    panel["boxes"] = boxes;
    panels.push_back(std::move(panel));
  }
  for (const Crop& crop : crops)
    for (const GridColumn& column : columns) {
      const PixelBox box = crop_pixels(crop, column.image->width, column.image->height);
      panels.push_back(image_panel(crop_image(*column.image, box), crop.label + " (enlarged)"));
    }
  if (baseline) {
    std::vector<std::vector<double>> differences;
    std::vector<double> all;
    for (const GridColumn& column : columns) {
      differences.push_back(column.image == baseline ? std::vector<double>{}
                            : displayed              ? displayed_difference(*column.image, *baseline)
                                                     : absolute_difference(*column.image, *baseline));
      all.insert(all.end(), differences.back().begin(), differences.back().end());
    }
    const double scale = std::max(quantile(all, 0.99), 1e-6);
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (differences[c].empty()) {
        panels.push_back({{"blank", true}});
        continue;
      }
      panels.push_back({{"title", fmt::format("{}\n(dark 0, bright ≥ {})", difference_title, format_number(scale, 2))},
                        {"width", columns[c].image->width},
                        {"height", columns[c].image->height},
                        {"heat", rounded(differences[c])},
                        {"scale", scale}});
    }
  }
  return panels;
}

nlohmann::json comparison_grid(const RenderedComparison& comparison, const std::vector<Crop>& crops) {
  std::vector<GridColumn> columns{{&comparison.reference, fmt::format("reference ({} spp)", comparison.reference_spp)}};
  for (std::size_t i = 0; i < comparison.rows.size(); ++i)
    columns.push_back({&comparison.images[i],
                       fmt::format("{}\nMSE {}", comparison.rows[i].label, format_number(comparison.rows[i].mse))});
  return picture_grid(columns, crops, &comparison.reference, "|error| against the reference");
}

RegionError region_error(const render::Image& image, const render::Image& reference, const PixelBox& box) {
  const render::Image crop = crop_image(image, box);
  return {masked_mean_squared_error(image, reference, box_mask(box, image.width, image.height)),
          mean_sample_variance(crop)};
}

RenderedComparison run_comparison(const render::ComparisonScene& scene,
                                  const std::vector<render::CompareConfig>& configs, std::uint32_t reference_spp,
                                  const std::string& cache_dir, double equal_time) {
  render::CompareOptions options;
  options.reference_spp = reference_spp;
  options.cache_dir = cache_dir;
  options.equal_time = equal_time;
  render::CompareImages pictures;
  RenderedComparison result;
  result.rows = render::compare(scene.scene, scene.key, configs, options, &pictures);
  result.images = std::move(pictures.images);
  result.reference = std::move(pictures.reference);
  result.reference_cached = pictures.reference_cached;
  result.reference_spp = reference_spp;
  double sum = 0;
  for (const double v : result.reference.variance) sum += v;
  result.reference_variance = result.reference.variance.empty() ? 0 : sum / double(result.reference.variance.size());
  return result;
}

double masked_mean_squared_error(const render::Image& image, const render::Image& reference,
                                 const std::vector<bool>& mask) {
  require(image.rgb.size() == reference.rgb.size() && mask.size() * 3 == image.rgb.size(), "mask", mask.size(),
          "must hold one flag per pixel of images of equal size");
  double sum = 0;
  std::size_t count = 0;
  for (std::size_t p = 0; p < mask.size(); ++p) {
    if (!mask[p]) continue;
    for (int c = 0; c < 3; ++c) {
      const double e = image.rgb[3 * p + c] - reference.rgb[3 * p + c];
      sum += e * e;
    }
    count += 3;
  }
  return count == 0 ? 0 : sum / double(count);
}

double mean_sample_variance(const render::Image& image) {
  if (image.variance.empty()) return 0;
  double sum = 0;
  for (const double v : image.variance) sum += v;
  return sum / double(image.variance.size()) * image.samples;
}

nlohmann::json image_panel(const render::Image& image, const std::string& title) {
  std::vector<double> rgb(image.rgb.size());
  for (std::size_t i = 0; i < rgb.size(); ++i)
    rgb[i] = std::isfinite(image.rgb[i]) ? std::round(image.rgb[i] * 1e4) / 1e4 : 0;
  return {{"title", title}, {"width", image.width}, {"height", image.height}, {"rgb", rgb}};
}

Figure image_figure(SectionContext& context, const nlohmann::json& panels, const std::string& name,
                    const std::string& caption, int columns) {
  nlohmann::json data = {{"panels", panels}};
  if (columns > 0) data["columns"] = columns;
  return context.plot("report_images", std::move(data), name, caption);
}

nlohmann::json comparison_panels(const RenderedComparison& comparison) {
  nlohmann::json panels = nlohmann::json::array();
  panels.push_back(image_panel(comparison.reference, fmt::format("reference ({} spp)", comparison.reference_spp)));
  for (std::size_t i = 0; i < comparison.rows.size(); ++i)
    panels.push_back(image_panel(comparison.images[i], fmt::format("{}\nMSE {}", comparison.rows[i].label,
                                                                   format_number(comparison.rows[i].mse))));
  return panels;
}

Table comparison_table(const RenderedComparison& comparison, const std::string& caption) {
  Table table{caption,
              {"configuration", "eye rays/pixel", "MSE", "relative MSE", "seconds", "efficiency 1/(MSE·s)",
               "MSE ratio (first/this)", "efficiency ratio (this/first)"},
              {}};
  for (const render::CompareRow& row : comparison.rows)
    table.rows.push_back({row.label, std::to_string(row.samples), format_number(row.mse),
                          format_number(row.relative_mse), format_number(row.seconds), format_number(row.efficiency),
                          format_number(row.mse_ratio), format_number(row.efficiency_ratio)});
  return table;
}

nlohmann::json comparison_numbers(const RenderedComparison& comparison) {
  nlohmann::json rows = nlohmann::json::object();
  for (std::size_t i = 0; i < comparison.rows.size(); ++i) {
    const render::CompareRow& row = comparison.rows[i];
    rows[row.label] = {{"spp", row.samples},
                       {"mse", row.mse},
                       {"relative_mse", row.relative_mse},
                       {"seconds", row.seconds},
                       {"efficiency", row.efficiency},
                       {"mse_ratio", row.mse_ratio},
                       {"efficiency_ratio", row.efficiency_ratio},
                       {"sample_variance", mean_sample_variance(comparison.images[i])}};
  }
  return {{"width", comparison.reference.width},
          {"height", comparison.reference.height},
          {"reference_spp", comparison.reference_spp},
          {"reference_cached", comparison.reference_cached},
          {"reference_variance", comparison.reference_variance},
          {"rows", rows}};
}

}  // namespace stratum::report
