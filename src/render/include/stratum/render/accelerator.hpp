#pragma once
/// Ray queries on a Scene through Embree 3 (Wald et al. 2014, "Embree: a
/// kernel framework for efficient CPU ray tracing"): triangles, quads,
/// spheres and exact disks (user geometry, disk_geometry.cpp), each with two
/// time steps when it moves, so that a ray's time
/// picks its position along the linear motion (motion blur). Thread-safe
/// after construction; one instance per scene, which must outlive it.
#include <cstddef>
#include <memory>
#include <optional>

#include "stratum/render/scene.hpp"

namespace stratum::render {

struct Ray {
  Vec3 origin;
  Vec3 direction;   ///< need not be unit length; t is in its units
  double time = 0;  ///< in [0, 1]: shutter open to shutter close
  double t_max = 1e300;
};

struct Hit {
  double t = 0;
  std::size_t shape = 0;      ///< index into Scene::shapes
  std::size_t primitive = 0;  ///< triangles: index into Shape::indices (0 for other shapes)
  Vec3 position;
  Vec3 normal;  ///< unit geometric normal, as the shape is oriented (not flipped to the ray)
};

class Accelerator {
 public:
  explicit Accelerator(const Scene& scene);
  ~Accelerator();
  Accelerator(const Accelerator&) = delete;
  Accelerator& operator=(const Accelerator&) = delete;

  /// The nearest hit with t in (epsilon, t_max), if any.
  std::optional<Hit> intersect(const Ray& ray) const;
  /// Is anything hit with t in (epsilon, t_max)? (shadow rays)
  bool occluded(const Ray& ray) const;
  /// Self-intersection offset along rays: a small fraction of the scene's size.
  double epsilon() const noexcept { return epsilon_; }
  /// The scene it was built from (which must outlive it).
  const Scene& scene() const noexcept { return *scene_; }

 private:
  struct Embree;
  std::unique_ptr<Embree> embree_;
  const Scene* scene_;
  double epsilon_ = 1e-4;
};

}  // namespace stratum::render
