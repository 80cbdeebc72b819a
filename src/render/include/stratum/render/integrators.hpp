#pragma once
/// Light transport estimators for one camera ray (LECTURE.md §2, §3, §9).
/// - direct: emitted light seen directly, plus M shadow rays towards the
///   lights from the first diffuse hit (after any mirror bounces), by area
///   sampling (pdf per area turned into solid angle by d²/cos θ_light) or by
///   solid angle (spherical rectangles for quads, Ureña, Fajardo, King 2013;
///   cones for spheres; spherical triangles for meshes and disks, Arvo 1995:
///   see lights.hpp); the M samples are drawn first and their shadow rays
///   traced after, so that their arithmetic overlaps;
/// - irradiance: the light reflected by the first diffuse hit from what one
///   bounce of hemisphere sampling finds (emitters or the environment):
///   ambient occlusion under a constant sky; uniform or cosine-weighted;
/// - path: path tracing with next-event estimation (M shadow rays at the
///   first vertex, one after) and Russian roulette (Arvo, Kirk 1990).
#include <cstdint>
#include <memory>

#include "stratum/render/accelerator.hpp"
#include "stratum/render/pixel_sampler.hpp"
#include "stratum/render/render.hpp"
#include "stratum/render/scene.hpp"

namespace stratum::render {

/// The settings' integrator prepared once per render: names parsed into
/// choices, the lights' geometry (normals, areas, emission) and the
/// environment computed, so that the per-ray path does no string compares
/// and no allocation. Scene, accelerator and settings must outlive it.
class Integrator {
 public:
  Integrator(const Scene& scene, const Accelerator& accelerator, const RenderSettings& settings);
  ~Integrator();
  Integrator(const Integrator&) = delete;
  Integrator& operator=(const Integrator&) = delete;

  /// Radiance (RGB) arriving along `ray`. Thread-safe (each thread its own sampler).
  Vec3 radiance(const Ray& ray, PixelSampler& sampler) const;

  struct Prepared;  ///< defined in integrators.cpp

 private:
  std::unique_ptr<const Prepared> prepared_;
};

/// Radiance (RGB) arriving along `ray`, by the settings' integrator
/// (prepares an Integrator for this one ray; render() keeps one).
Vec3 radiance(const Scene& scene, const Accelerator& accelerator, const RenderSettings& settings, const Ray& ray,
              PixelSampler& sampler);

}  // namespace stratum::render
