#pragma once
/// Camera rays: the camera integral of LECTURE.md §1. A pixel sample picks
/// the film position, a lens sample the point on the thin lens (through
/// Shirley and Chiu's concentric disk map, so stratified lens samples stay
/// stratified), a time sample the instant within the shutter (Cook, Porter,
/// Carpenter 1984, "Distributed ray tracing").
#include <array>

#include "stratum/render/accelerator.hpp"
#include "stratum/render/scene.hpp"

namespace stratum::render {

class CameraModel {
 public:
  explicit CameraModel(const Camera& camera);

  /// The ray through film position (x, y) in pixels (x right, y down, (0,0)
  /// the top-left corner of the image), lens sample `lens` ∈ [0,1)², at
  /// shutter fraction `time` ∈ [0,1). Directions are unit length.
  Ray generate(double x, double y, std::array<double, 2> lens, double time) const noexcept;

  int width() const noexcept { return width_; }
  int height() const noexcept { return height_; }

 private:
  Vec3 position_, forward_, right_, up_;
  double tan_half_ = 0, aspect_ = 1, aperture_ = 0, focus_ = 1;
  int width_ = 1, height_ = 1;
};

}  // namespace stratum::render
