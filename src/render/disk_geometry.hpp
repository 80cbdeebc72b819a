#pragma once
/// Exact disks in Embree 3 as user geometry: Embree has no disk primitive,
/// and a polygon inscribed in the disk changes both the shape's silhouette
/// and the light's area. The callbacks intersect the ray with the disk's
/// plane at the ray's time (linear motion) in double precision and keep the
/// hit when it lies within the radius (pbrt-v4 §6.5, "Disks").
#include <embree3/rtcore.h>

#include "stratum/render/scene.hpp"

namespace stratum::render {

/// A committed-ready user geometry of one primitive for `disk` (its
/// ShapeType::disk fields); `disk` must outlive the Embree scene.
RTCGeometry make_disk_geometry(RTCDevice device, const Shape& disk);

/// The ray parameter where the ray o + t·d meets the disk at `time`, or a
/// negative value when it misses (parallel to the plane, or outside the
/// radius). The geometric core of the callbacks, exposed for tests.
double intersect_disk(const Shape& disk, Vec3 origin, Vec3 direction, double time) noexcept;

}  // namespace stratum::render
