/// §1 The camera integral: a pixel's value integrates over the pixel area,
/// the lens and the shutter time (Cook, Porter, Carpenter 1984, "Distributed
/// ray tracing"). Each of the two effects is shown on its own, against the
/// same box through a pinhole with nothing moving:
///  - depth of field: a thin lens focused on the sphere (near) and on the
///    back wall (far), with crops of the sphere's edge and of the back
///    corner and a heat map of what the lens changes, and a sharpness
///    statistic (mean squared luminance gradient) in each crop;
///  - motion blur: the sphere moving during the shutter, with a crop of its
///    path and a heat map of what the motion changes, inside and outside
///    the band its silhouette sweeps.
#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "render_support.hpp"
#include "sections.hpp"

namespace stratum::report {

namespace {

/// Where `point` appears on `camera`'s film, in pixels (x right, y down),
/// the inverse of render::CameraModel's pinhole ray.
std::array<double, 2> pixel_of(const render::Camera& camera, render::Vec3 point) {
  const render::Vec3 forward = normalize(camera.look_at - camera.position);
  const render::Vec3 right = normalize(cross(forward, camera.up));
  const render::Vec3 up = cross(right, forward);
  const double tan_half = std::tan(camera.fov_degrees * std::numbers::pi / 360);
  const double aspect = double(camera.width) / camera.height;
  const render::Vec3 d = point - camera.position;
  const double depth = dot(d, forward);
  const double sx = dot(d, right) / depth / (tan_half * aspect), sy = dot(d, up) / depth / tan_half;
  return {(sx + 1) / 2 * camera.width, (1 - sy) / 2 * camera.height};
}

/// A square crop of side `side` (a fraction of the image) centred on pixel `at`.
Crop crop_around(std::array<double, 2> at, const render::Camera& camera, double side, const std::string& label) {
  const double x = std::clamp(at[0] / camera.width - side / 2, 0.0, 1 - side);
  const double y = std::clamp(at[1] / camera.height - side / 2, 0.0, 1 - side);
  return {x, y, side, side, label};
}

/// Mean squared central-difference gradient of the displayed luminance
/// (each channel clamped to [0, 1] and sRGB-encoded, as the PNG shows it)
/// over the pixels of `box` away from the image's border: high where edges
/// are sharp, lower where the lens spreads them.
double sharpness(const render::Image& image, const PixelBox& box) {
  const int w = image.width, h = image.height;
  std::vector<double> shown(std::size_t(w) * h);
  for (std::size_t p = 0; p < shown.size(); ++p) {
    double l = 0;
    for (int c = 0; c < 3; ++c) {
      const double v = std::clamp(image.rgb[3 * p + c], 0.0, 1.0);
      l += std::array{0.2126, 0.7152, 0.0722}[c] * (v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055);
    }
    shown[p] = l;
  }
  double sum = 0;
  int count = 0;
  for (int y = std::max(box.y, 1); y < std::min(box.y + box.height, h - 1); ++y)
    for (int x = std::max(box.x, 1); x < std::min(box.x + box.width, w - 1); ++x) {
      const double gx = (shown[std::size_t(y) * w + x + 1] - shown[std::size_t(y) * w + x - 1]) / 2;
      const double gy = (shown[std::size_t(y + 1) * w + x] - shown[std::size_t(y - 1) * w + x]) / 2;
      sum += gx * gx + gy * gy;
      ++count;
    }
  return count ? sum / count : 0;
}

/// Mean of `values` over the pixels where `mask` is `inside`.
double masked_mean(const std::vector<double>& values, const std::vector<bool>& mask, bool inside) {
  double sum = 0;
  std::size_t count = 0;
  for (std::size_t p = 0; p < values.size(); ++p)
    if (mask[p] == inside) sum += values[p], ++count;
  return count ? sum / double(count) : 0;
}

}  // namespace

Section camera_section(SectionContext& context) {
  Section section = context.start();
  // 64×64 in the quick report: at 32 pixels the blur circles are a pixel wide.
  const int size = context.quick() ? 64 : picture_scale(context).width;
  render::Scene still = render::cornell_box();
  still.camera.width = still.camera.height = size;
  still.camera.aperture_radius = 0;
  std::size_t ball = 0;  // the moving shape (the sphere)
  render::Vec3 motion{};
  for (std::size_t s = 0; s < still.shapes.size(); ++s)
    if (length(still.shapes[s].motion) > length(motion)) motion = still.shapes[s].motion, ball = s;
  for (auto& shape : still.shapes) shape.motion = {};
  const render::Vec3 ball_centre = still.shapes[ball].center;
  const double ball_radius = still.shapes[ball].radius;

  // Depth of field: a lens far wider than a real 35 mm lens's (f/0.3), so
  // that the blur circles are many pixels wide at this image size.
  const double aperture = 60;
  const double back_wall = 559.2 - still.camera.position.z;  // the box's back wall is at z = 559.2
  const double sphere_depth = ball_centre.z - still.camera.position.z;
  render::Scene near_focus = still, far_focus = still, moving = still;
  near_focus.camera.aperture_radius = far_focus.camera.aperture_radius = aperture;
  near_focus.camera.focus_distance = sphere_depth;
  far_focus.camera.focus_distance = back_wall;
  moving.shapes[ball].motion = motion;

  render::RenderSettings settings;
  // Direct lighting: far less noise than path tracing at the same cost, and
  // the unlit ceiling makes the back corner's edges stark.
  settings.integrator = "direct";
  settings.light_samples = 2;
  settings.sampler.spp = context.quick() ? 16 : 64;
  settings.sampler.seed = context.seed();
  settings.threads = context.threads();
  const render::Image pinhole = render::render(still, settings);
  const render::Image near_image = render::render(near_focus, settings);
  const render::Image far_image = render::render(far_focus, settings);
  const render::Image moving_image = render::render(moving, settings);

  // The crops: the sphere's left edge (in the near focus plane) and the
  // corner of the red wall, back wall and ceiling (in the far one).
  const auto& camera = still.camera;
  const Crop near_crop =
      crop_around(pixel_of(camera, ball_centre + render::Vec3{ball_radius, 0, 0}), camera, 0.25, "sphere's edge");
  const Crop far_crop = crop_around(pixel_of(camera, {556, 548.8, 559.2}), camera, 0.25, "back corner");
  const std::array<double, 2> from = pixel_of(camera, ball_centre), to = pixel_of(camera, ball_centre + motion);
  const double swept_pixels = std::hypot(to[0] - from[0], to[1] - from[1]);
  const double radius_pixels =
      ball_radius / sphere_depth / std::tan(camera.fov_degrees * std::numbers::pi / 360) * size / 2;
  const std::array<double, 2> middle{(from[0] + to[0]) / 2, (from[1] + to[1]) / 2};
  const Crop motion_crop =
      crop_around(middle, camera, std::min(1.0, (2 * radius_pixels + swept_pixels) / size + 0.06), "sphere's path");

  const std::string lens_words = fmt::format("lens radius {} mm", format_number(aperture));
  section.figures.push_back(image_figure(
      context,
      picture_grid(
          {{&pinhole, "pinhole"},
           {&near_image, fmt::format("{}\nfocused on the sphere ({} mm)", lens_words, format_number(sphere_depth))},
           {&far_image, fmt::format("{}\nfocused on the back wall ({} mm)", lens_words, format_number(back_wall))}},
          {near_crop, far_crop}, &pinhole, "|lens − pinhole| as displayed", true),
      "depth-of-field",
      fmt::format("Depth of field: the box through a pinhole and through a thin lens of radius {} mm focused near "
                  "and far, {}×{} pixels, {} samples per pixel, nothing moving; the outlined crops enlarged below, "
                  "and where each lens render differs from the pinhole one",
                  format_number(aperture), size, size, settings.sampler.spp),
      3));
  section.figures.push_back(image_figure(
      context,
      picture_grid(
          {{&pinhole, "still"}, {&moving_image, fmt::format("sphere moving {} mm", format_number(length(motion)))}},
          {motion_crop}, &pinhole, "|moving − still| as displayed", true),
      "motion-blur",
      fmt::format("Motion blur: the sphere still and moving {} mm while the shutter is open (pinhole), {}×{} "
                  "pixels, {} samples per pixel; its path enlarged, and where the moving render differs from the "
                  "still one",
                  format_number(length(motion)), size, size, settings.sampler.spp),
      2));

  // Sharpness in each crop, and the motion's footprint.
  const PixelBox near_box = crop_pixels(near_crop, size, size), far_box = crop_pixels(far_crop, size, size);
  struct Named {
    const char* key;
    const char* label;
    const render::Image* image;
  };
  const Named lens_renders[] = {{"pinhole", "pinhole", &pinhole},
                                {"near_focus", "focused on the sphere", &near_image},
                                {"far_focus", "focused on the back wall", &far_image}};
  Table sharp{"Sharpness in each crop: mean squared gradient of the displayed luminance",
              {"render", "sphere's edge (near)", "back corner (far)", "seconds"},
              {}};
  for (const Named& r : lens_renders) {
    const double near_sharpness = sharpness(*r.image, near_box), far_sharpness = sharpness(*r.image, far_box);
    sharp.rows.push_back(
        {r.label, format_number(near_sharpness), format_number(far_sharpness), format_number(r.image->seconds)});
    section.numbers["depth_of_field"][r.key] = {
        {"sharpness_near", near_sharpness}, {"sharpness_far", far_sharpness}, {"seconds", r.image->seconds}};
  }
  section.tables.push_back(std::move(sharp));
  auto& dof = section.numbers["depth_of_field"];
  dof["near_box"] = {near_box.x, near_box.y, near_box.width, near_box.height};
  dof["far_box"] = {far_box.x, far_box.y, far_box.width, far_box.height};

  // The band the silhouette sweeps: pixels within the sphere's image radius
  // of the segment its centre's image travels (a slight overestimate: the
  // silhouette of a sphere off the axis is an ellipse a little wider than that).
  std::vector<bool> swept(std::size_t(size) * size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const double px = x + 0.5 - from[0], py = y + 0.5 - from[1];
      const double dx = to[0] - from[0], dy = to[1] - from[1];
      const double t = std::clamp((px * dx + py * dy) / (dx * dx + dy * dy), 0.0, 1.0);
      swept[std::size_t(y) * size + x] = std::hypot(px - t * dx, py - t * dy) <= radius_pixels + 1.5;
    }
  const std::vector<double> motion_difference = absolute_difference(moving_image, pinhole);
  const double inside = masked_mean(motion_difference, swept, true),
               outside = masked_mean(motion_difference, swept, false);
  const std::size_t swept_count = std::size_t(std::count(swept.begin(), swept.end(), true));
  Table blur{"Where the motion changes the image: mean |moving − still| luminance",
             {"pixels", "count", "mean |difference|"},
             {}};
  blur.rows.push_back({"in the band the silhouette sweeps", std::to_string(swept_count), format_number(inside)});
  blur.rows.push_back({"elsewhere", std::to_string(swept.size() - swept_count), format_number(outside)});
  section.tables.push_back(std::move(blur));

  section.numbers["width"] = size;
  section.numbers["height"] = size;
  section.numbers["spp"] = settings.sampler.spp;
  section.numbers["integrator"] = settings.integrator;
  section.numbers["threads"] = settings.threads;
  section.numbers["aperture_radius"] = aperture;
  section.numbers["near_focus_distance"] = sphere_depth;
  section.numbers["far_focus_distance"] = back_wall;
  section.numbers["motion_mm"] = length(motion);
  section.numbers["motion_blur"] = {{"swept_pixels", swept_pixels},       {"sphere_radius_pixels", radius_pixels},
                                    {"band_pixels", swept_count},         {"mean_difference_inside", inside},
                                    {"mean_difference_outside", outside}, {"seconds", moving_image.seconds}};

  section.text.push_back(
      "A pixel's value R = ∫∫∫ L(x, ω, t) P(x) S(t) cos θ dA dω dt integrates over the pixel area, the lens and the "
      "shutter time: every eye ray takes a film position, a lens position and a time, so that one Monte Carlo "
      "estimate gives antialiasing, depth of field and motion blur together.");
  const auto& near_n = dof["near_focus"];
  const auto& far_n = dof["far_focus"];
  section.text.push_back(fmt::format(
      "Depth of field: a thin lens of radius {} mm brings one plane into focus. Focused on the sphere ({} mm from "
      "the camera), the sphere's edge keeps a sharpness (mean squared gradient in its crop) of {} against the "
      "pinhole's {}, while the back corner, {} mm away, blurs to {}; focused on the back wall, the corner keeps {} "
      "and the sphere's edge falls to {}. The heat maps show where the lens changes the picture: everywhere but "
      "the plane in focus.",
      format_number(aperture), format_number(sphere_depth), format_number(near_n["sharpness_near"]),
      format_number(dof["pinhole"]["sharpness_near"]), format_number(back_wall), format_number(near_n["sharpness_far"]),
      format_number(far_n["sharpness_far"]), format_number(far_n["sharpness_near"])));
  section.text.push_back(fmt::format(
      "Motion blur: the sphere moves {} mm while the shutter is open, {} pixels on the film (its image is {} pixels "
      "in radius). Inside the band its silhouette sweeps the moving render differs from the still one by {} on "
      "average, elsewhere by {} (the noise of two renders); each render of {} samples per pixel at {}×{} took "
      "about {}.",
      format_number(length(motion)), format_number(swept_pixels, 2), format_number(radius_pixels, 2),
      format_number(inside), format_number(outside), settings.sampler.spp, size, size,
      format_seconds(moving_image.seconds)));
  section.try_it = {"stratum render --spp 16 --sampler sobol --randomize owen --width 128 --height 128 -o box.png"};
  return section;
}

}  // namespace stratum::report
