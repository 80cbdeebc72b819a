#include "stratum/render/accelerator.hpp"

#include <embree3/rtcore.h>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "disk_geometry.hpp"

namespace stratum::render {

struct Accelerator::Embree {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<std::size_t> shape_of_geometry;
  std::vector<Vec3> quad_normals;  ///< by shape: unit edge_u × edge_v of quads, disks' normals (once, not per hit)
  /// by shape, by triangle: unit (v1 − v0) × (v2 − v0), computed once: per
  /// hit it would read the index and three vertices, cache misses on a large mesh.
  std::vector<std::vector<Vec3>> triangle_normals;
  ~Embree() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

namespace {

bool moves(const Shape& shape) { return shape.motion.x != 0 || shape.motion.y != 0 || shape.motion.z != 0; }

void check(RTCDevice device, const char* what) {
  const RTCError error = rtcGetDeviceError(device);
  if (error != RTC_ERROR_NONE)
    throw std::runtime_error(std::string("Embree: ") + what + " failed (error " + std::to_string(error) + ")");
}

/// Vertex buffers for each time step: the positions at shutter open and,
/// for moving shapes, at shutter close.
template <class Fill>
void set_vertices(RTCGeometry geometry, const Shape& shape, RTCFormat format, std::size_t stride, std::size_t count,
                  Fill fill) {
  const unsigned steps = moves(shape) ? 2 : 1;
  rtcSetGeometryTimeStepCount(geometry, steps);
  for (unsigned step = 0; step < steps; ++step) {
    auto* data =
        static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, step, format, stride, count));
    fill(data, step == 0 ? Vec3{} : shape.motion);
  }
}

RTCGeometry make_geometry(RTCDevice device, const Shape& shape) {
  RTCGeometry geometry = nullptr;
  if (shape.type == ShapeType::disk) {
    geometry = make_disk_geometry(device, shape);
  } else if (shape.type == ShapeType::sphere) {
    geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
    set_vertices(geometry, shape, RTC_FORMAT_FLOAT4, 4 * sizeof(float), 1, [&](float* v, Vec3 shift) {
      const Vec3 c = shape.center + shift;
      v[0] = float(c.x), v[1] = float(c.y), v[2] = float(c.z), v[3] = float(shape.radius);
    });
  } else if (shape.type == ShapeType::quad) {
    geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_QUAD);
    set_vertices(geometry, shape, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 4, [&](float* v, Vec3 shift) {
      const Vec3 corners[4] = {shape.corner, shape.corner + shape.edge_u, shape.corner + shape.edge_u + shape.edge_v,
                               shape.corner + shape.edge_v};
      for (int i = 0; i < 4; ++i) {
        const Vec3 p = corners[i] + shift;
        v[3 * i] = float(p.x), v[3 * i + 1] = float(p.y), v[3 * i + 2] = float(p.z);
      }
    });
    auto* index = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT4, 4 * sizeof(unsigned), 1));
    for (unsigned i = 0; i < 4; ++i) index[i] = i;
  } else {
    geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    set_vertices(geometry, shape, RTC_FORMAT_FLOAT3, 3 * sizeof(float), shape.vertices.size(),
                 [&](float* v, Vec3 shift) {
                   for (std::size_t i = 0; i < shape.vertices.size(); ++i) {
                     const Vec3 p = shape.vertices[i] + shift;
                     v[3 * i] = float(p.x), v[3 * i + 1] = float(p.y), v[3 * i + 2] = float(p.z);
                   }
                 });
    auto* index = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                 3 * sizeof(unsigned), shape.indices.size()));
    for (std::size_t t = 0; t < shape.indices.size(); ++t)
      for (int k = 0; k < 3; ++k) index[3 * t + k] = shape.indices[t][k];
  }
  return geometry;
}

/// Largest coordinate magnitude over the scene (shapes at both time steps).
double scene_extent(const Scene& scene) {
  double extent = 1;
  auto grow = [&](Vec3 p) { extent = std::max({extent, std::abs(p.x), std::abs(p.y), std::abs(p.z)}); };
  for (const Shape& shape : scene.shapes) {
    for (Vec3 shift : {Vec3{}, shape.motion}) {
      if (shape.type == ShapeType::sphere || shape.type == ShapeType::disk)
        grow(shape.center + shift + Vec3{shape.radius, shape.radius, shape.radius});
      if (shape.type == ShapeType::quad)
        grow(shape.corner + shift), grow(shape.corner + shape.edge_u + shape.edge_v + shift);
      for (Vec3 v : shape.vertices) grow(v + shift);
    }
  }
  return extent;
}

RTCRay to_embree(const Ray& ray, double t_near) {
  RTCRay r;  // every field set below
  r.org_x = float(ray.origin.x), r.org_y = float(ray.origin.y), r.org_z = float(ray.origin.z);
  r.dir_x = float(ray.direction.x), r.dir_y = float(ray.direction.y), r.dir_z = float(ray.direction.z);
  r.tnear = float(t_near);
  r.tfar = ray.t_max >= double(std::numeric_limits<float>::max()) ? std::numeric_limits<float>::infinity()
                                                                  : float(ray.t_max);
  r.time = float(ray.time);
  r.mask = ~0u;
  r.id = 0;
  r.flags = 0;
  return r;
}

}  // namespace

Accelerator::Accelerator(const Scene& scene) : embree_(std::make_unique<Embree>()), scene_(&scene) {
  embree_->device = rtcNewDevice(nullptr);
  if (!embree_->device) throw std::runtime_error("Embree: cannot create a device");
  embree_->scene = rtcNewScene(embree_->device);
  embree_->quad_normals.resize(scene.shapes.size());
  embree_->triangle_normals.resize(scene.shapes.size());
  for (std::size_t s = 0; s < scene.shapes.size(); ++s) {
    const Shape& shape = scene.shapes[s];
    if (shape.type == ShapeType::quad) embree_->quad_normals[s] = normalize(cross(shape.edge_u, shape.edge_v));
    if (shape.type == ShapeType::disk) embree_->quad_normals[s] = shape.normal;
    if (shape.type == ShapeType::triangles)
      for (const auto& tri : shape.indices) {
        const Vec3 a = shape.vertices[tri[0]], b = shape.vertices[tri[1]], c = shape.vertices[tri[2]];
        embree_->triangle_normals[s].push_back(normalize(cross(b - a, c - a)));
      }
    if (shape.type == ShapeType::triangles && shape.indices.empty()) continue;
    RTCGeometry geometry = make_geometry(embree_->device, shape);
    rtcCommitGeometry(geometry);
    const unsigned id = rtcAttachGeometry(embree_->scene, geometry);
    rtcReleaseGeometry(geometry);
    if (embree_->shape_of_geometry.size() <= id) embree_->shape_of_geometry.resize(id + 1);
    embree_->shape_of_geometry[id] = s;
  }
  rtcCommitScene(embree_->scene);
  check(embree_->device, "building the scene");
  // Embree works in float: offsets of a few float ulps of the scene's size.
  epsilon_ = 1e-5 * scene_extent(scene);
}

Accelerator::~Accelerator() = default;

std::optional<Hit> Accelerator::intersect(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit query;  // Embree reads the ray and these two hit fields, and writes the rest
  query.ray = to_embree(ray, epsilon_);
  query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(embree_->scene, &context, &query);
  if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  Hit hit;
  hit.t = query.ray.tfar;
  hit.shape = embree_->shape_of_geometry[query.hit.geomID];
  hit.position = ray.origin + hit.t * ray.direction;
  // Normals from the shape itself, so that their orientation follows the
  // scene's conventions (edge_u × edge_v; (v1 − v0) × (v2 − v0); outwards).
  const Shape& shape = scene_->shapes[hit.shape];
  if (shape.type == ShapeType::sphere) {
    hit.normal = normalize(hit.position - (shape.center + ray.time * shape.motion));
  } else if (shape.type == ShapeType::quad || shape.type == ShapeType::disk) {
    hit.normal = embree_->quad_normals[hit.shape];
  } else {
    hit.primitive = query.hit.primID;
    hit.normal = embree_->triangle_normals[hit.shape][query.hit.primID];
  }
  return hit;
}

bool Accelerator::occluded(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay query = to_embree(ray, epsilon_);
  rtcOccluded1(embree_->scene, &context, &query);
  return query.tfar < 0;  // Embree sets tfar to −inf on a hit
}

}  // namespace stratum::render
