#include "disk_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stratum::render {

namespace {

/// Bounds at Embree's time step (0: shutter open, 1: close): the disk's
/// extent along each axis is r·sqrt(1 − n_axis²).
void disk_bounds(const RTCBoundsFunctionArguments* args) {
  const Shape& disk = *static_cast<const Shape*>(args->geometryUserPtr);
  const Vec3 c = disk.center + double(args->timeStep) * disk.motion;
  const Vec3 n = disk.normal;
  const Vec3 e{disk.radius * std::sqrt(std::max(0.0, 1 - n.x * n.x)),
               disk.radius * std::sqrt(std::max(0.0, 1 - n.y * n.y)),
               disk.radius * std::sqrt(std::max(0.0, 1 - n.z * n.z))};
  // Rounded outwards to float, with a relative margin for the conversion.
  const auto lo = [](double v, double half) { return std::nextafter(float(v - half * (1 + 1e-6)), -INFINITY); };
  const auto hi = [](double v, double half) { return std::nextafter(float(v + half * (1 + 1e-6)), INFINITY); };
  args->bounds_o->lower_x = lo(c.x, e.x), args->bounds_o->upper_x = hi(c.x, e.x);
  args->bounds_o->lower_y = lo(c.y, e.y), args->bounds_o->upper_y = hi(c.y, e.y);
  args->bounds_o->lower_z = lo(c.z, e.z), args->bounds_o->upper_z = hi(c.z, e.z);
}

struct RayView {
  Vec3 origin, direction;
  double t_near, t_far, time;
};

RayView view_of(RTCRayN* ray, unsigned n, unsigned i) {
  return {{RTCRayN_org_x(ray, n, i), RTCRayN_org_y(ray, n, i), RTCRayN_org_z(ray, n, i)},
          {RTCRayN_dir_x(ray, n, i), RTCRayN_dir_y(ray, n, i), RTCRayN_dir_z(ray, n, i)},
          RTCRayN_tnear(ray, n, i),
          RTCRayN_tfar(ray, n, i),
          RTCRayN_time(ray, n, i)};
}

void disk_intersect(const RTCIntersectFunctionNArguments* args) {
  const Shape& disk = *static_cast<const Shape*>(args->geometryUserPtr);
  RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, args->N);
  RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, args->N);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    const RayView r = view_of(ray, args->N, i);
    const double t = intersect_disk(disk, r.origin, r.direction, r.time);
    if (!(t > r.t_near && t < r.t_far)) continue;
    RTCRayN_tfar(ray, args->N, i) = float(t);
    RTCHitN_Ng_x(hit, args->N, i) = float(disk.normal.x);
    RTCHitN_Ng_y(hit, args->N, i) = float(disk.normal.y);
    RTCHitN_Ng_z(hit, args->N, i) = float(disk.normal.z);
    RTCHitN_u(hit, args->N, i) = 0;
    RTCHitN_v(hit, args->N, i) = 0;
    RTCHitN_primID(hit, args->N, i) = args->primID;
    RTCHitN_geomID(hit, args->N, i) = args->geomID;
    RTCHitN_instID(hit, args->N, i, 0) = args->context->instID[0];
  }
}

void disk_occluded(const RTCOccludedFunctionNArguments* args) {
  const Shape& disk = *static_cast<const Shape*>(args->geometryUserPtr);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    const RayView r = view_of(args->ray, args->N, i);
    const double t = intersect_disk(disk, r.origin, r.direction, r.time);
    if (t > r.t_near && t < r.t_far) RTCRayN_tfar(args->ray, args->N, i) = -INFINITY;  // Embree's "occluded"
  }
}

}  // namespace

double intersect_disk(const Shape& disk, Vec3 origin, Vec3 direction, double time) noexcept {
  const Vec3 c = disk.center + time * disk.motion;
  const double along = dot(direction, disk.normal);
  if (along == 0) return -1;
  const double t = dot(c - origin, disk.normal) / along;
  const Vec3 offset = origin + t * direction - c;
  if (!(dot(offset, offset) <= disk.radius * disk.radius)) return -1;
  return t;
}

RTCGeometry make_disk_geometry(RTCDevice device, const Shape& disk) {
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
  const bool moves = disk.motion.x != 0 || disk.motion.y != 0 || disk.motion.z != 0;
  rtcSetGeometryTimeStepCount(geometry, moves ? 2 : 1);
  rtcSetGeometryUserPrimitiveCount(geometry, 1);
  rtcSetGeometryUserData(geometry, const_cast<Shape*>(&disk));
  rtcSetGeometryBoundsFunction(geometry, disk_bounds, const_cast<Shape*>(&disk));
  rtcSetGeometryIntersectFunction(geometry, disk_intersect);
  rtcSetGeometryOccludedFunction(geometry, disk_occluded);
  return geometry;
}

}  // namespace stratum::render
