#include "stratum/render/camera_model.hpp"

#include <cmath>
#include <numbers>

#include "stratum/warps/disk.hpp"

namespace stratum::render {

CameraModel::CameraModel(const Camera& camera)
    : position_(camera.position),
      forward_(normalize(camera.look_at - camera.position)),
      tan_half_(std::tan(camera.fov_degrees * std::numbers::pi / 360)),
      aspect_(double(camera.width) / double(camera.height)),
      aperture_(camera.aperture_radius),
      focus_(camera.focus_distance),
      width_(camera.width),
      height_(camera.height) {
  // forward × up points to the image's right in a right-handed frame (the
  // Cornell box's red wall, at large x, appears on the left).
  right_ = normalize(cross(forward_, camera.up));
  up_ = cross(right_, forward_);
}

Ray CameraModel::generate(double x, double y, std::array<double, 2> lens, double time) const noexcept {
  const double sx = (2 * x / width_ - 1) * tan_half_ * aspect_;
  const double sy = (1 - 2 * y / height_) * tan_half_;
  const Vec3 through = forward_ + sx * right_ + sy * up_;  // a point at unit distance along forward
  if (aperture_ <= 0) return Ray{position_, normalize(through), time};
  // Thin lens: every ray from this film point meets the others on the plane
  // in focus, focus_ along forward.
  const Vec3 focused = position_ + focus_ * through;
  const auto disk = sample_concentric_disk(lens);
  const Vec3 origin = position_ + aperture_ * (disk[0] * right_ + disk[1] * up_);
  return Ray{origin, normalize(focused - origin), time};
}

}  // namespace stratum::render
