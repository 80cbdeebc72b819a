/// §1 The camera integral: a pixel's value integrates over the pixel area,
/// the lens and the shutter time (Cook, Porter, Carpenter 1984, "Distributed
/// ray tracing"). The default scene (render::cornell_box(): a thin lens
/// focused on the tall block, a sphere moving during the shutter) is
/// rendered beside the same box through a pinhole with nothing moving, so
/// that the depth of field and the motion blur show by contrast.
#include <fmt/core.h>

#include "render_support.hpp"
#include "sections.hpp"

namespace stratum::report {

namespace {

struct CameraRender {
  render::Image image;
  double rays_per_second = 0;
};

CameraRender render_measured(const render::Scene& scene, const render::RenderSettings& settings) {
  CameraRender result{render::render(scene, settings)};
  result.rays_per_second = double(result.image.width) * result.image.height * result.image.samples / result.image.seconds;
  return result;
}

}  // namespace

Section camera_section(SectionContext& context) {
  Section section = context.start();
  const int size = context.quick() ? 32 : 160;
  render::Scene lens_scene = render::cornell_box();
  lens_scene.camera.width = lens_scene.camera.height = size;
  render::Scene pinhole_scene = lens_scene;
  pinhole_scene.camera.aperture_radius = 0;
  render::Vec3 motion{};
  for (auto& shape : pinhole_scene.shapes) {
    if (length(shape.motion) > length(motion)) motion = shape.motion;
    shape.motion = {};
  }

  render::RenderSettings settings;
  settings.integrator = "path";
  settings.sampler.spp = context.quick() ? 16 : 64;
  settings.sampler.seed = context.seed();
  settings.threads = context.threads();
  const CameraRender lens = render_measured(lens_scene, settings);
  const CameraRender pinhole = render_measured(pinhole_scene, settings);

  const auto& camera = lens_scene.camera;
  nlohmann::json panels = nlohmann::json::array();
  panels.push_back(image_panel(lens.image, fmt::format("thin lens (aperture radius {} mm), moving sphere", format_number(camera.aperture_radius))));
  panels.push_back(image_panel(pinhole.image, "pinhole, nothing moving"));
  section.figures.push_back(image_figure(
      context, panels, "renders",
      fmt::format("The Cornell box, {}×{} pixels, {} samples per pixel ({} sampler `{}`): left, the default scene (lens "
                  "focused at {} mm, sphere moving by {} mm while the shutter is open); right, the same box through a "
                  "pinhole with the sphere held still",
                  size, size, settings.sampler.spp, sampler_name(settings.sampler.sampler, ""), settings.sampler.sampler, format_number(camera.focus_distance),
                  format_number(length(motion))),
      2));

  Table table{"Measured cost of each render", {"render", "pixels", "samples/pixel", "seconds", "eye rays/second"}, {}};
  for (const auto& [label, measured] : {std::pair{"thin lens, moving sphere", &lens}, std::pair{"pinhole, static", &pinhole}})
    table.rows.push_back({label, fmt::format("{}×{}", size, size), std::to_string(measured->image.samples),
                          format_number(measured->image.seconds), format_number(measured->rays_per_second)});
  section.tables.push_back(std::move(table));

  section.numbers = {{"width", size},
                     {"height", size},
                     {"spp", settings.sampler.spp},
                     {"integrator", settings.integrator},
                     {"threads", settings.threads},
                     {"aperture_radius", camera.aperture_radius},
                     {"focus_distance", camera.focus_distance},
                     {"motion_mm", length(motion)},
                     {"lens", {{"seconds", lens.image.seconds}, {"rays_per_second", lens.rays_per_second}}},
                     {"pinhole", {{"seconds", pinhole.image.seconds}, {"rays_per_second", pinhole.rays_per_second}}}};

  section.text.push_back(
      "A pixel's value R = ∫∫∫ L(x, ω, t) P(x) S(t) cos θ dA dω dt integrates over the pixel area, the lens and the "
      "shutter time: every eye ray takes a film position, a lens position and a time, so that one Monte Carlo "
      "estimate gives antialiasing, depth of field and motion blur together.");
  section.text.push_back(fmt::format(
      "Path traced with {} samples per pixel at {}×{} on {}, the default scene took {} ({} eye rays per "
      "second) and the pinhole, static box {} ({} eye rays per second).",
      settings.sampler.spp, size, size, counted(settings.threads, "thread"), format_seconds(lens.image.seconds),
      format_number(lens.rays_per_second), format_seconds(pinhole.image.seconds), format_number(pinhole.rays_per_second)));
  section.try_it = {"stratum render --spp 16 --sampler sobol --randomize owen --width 128 --height 128 -o box.png"};
  return section;
}

}  // namespace stratum::report
