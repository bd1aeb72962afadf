// The types every part meets at: rays, hits, ray types and triangle geometry.
// workloads/ produces them, model/ consumes them; neither includes the other.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "traces/alpha.h"

namespace rtsim {

// The ray types of the hybrid pipeline (SEED Pica Pica), in stream order.
enum class RayType : uint8_t {
  Camera = 0,
  Shadow = 1,
  Reflection = 2,
  ReflectedShadow = 3,
  DiffuseGI = 4,
  AO = 5,
  Refraction = 6,
  Translucency = 7,
};
constexpr int kRayTypeCount = 8;

enum class Query : uint8_t {
  ClosestHit = 0,  // find the nearest intersection in [tmin, tmax]
  AnyHit = 1,      // stop at the first intersection found (occlusion)
};

// Short lowercase names used in files, stats and reports ("camera", "diffuse_gi", ...).
const char* ray_type_name(RayType type);
std::optional<RayType> ray_type_from_name(const std::string& name);
const char* query_name(Query query);

struct Ray {
  glm::vec3 org{0.0f};
  glm::vec3 dir{0.0f, 0.0f, 1.0f};
  float tmin = 0.0f;
  float tmax = std::numeric_limits<float>::infinity();
  RayType type = RayType::Camera;
  Query query = Query::ClosestHit;
  // DXR's RAY_FLAG_FORCE_OPAQUE: alpha-tested triangles (traces/alpha.h) count as opaque, with no
  // any-hit alpha test; set per ray type by a workload's [alpha_test].
  bool force_opaque = false;
  uint16_t sample = 0;  // sample index within the pixel
  uint32_t pixel = 0;   // y * width + x of the pixel this ray contributes to
  uint32_t frame = 0;

  bool operator==(const Ray& o) const;
};

// The largest origin or direction component a ray may have: Embree's valid range (FLT_LARGE;
// its ray.valid() assertion aborts the process beyond it).
constexpr float kMaxRayComponent = 1.844e18f;

// Why a ray cannot be traced (NaN or Inf fields, components beyond kMaxRayComponent, zero
// direction, tmin > tmax); empty if fine. tmax = +inf is allowed; denormal directions are
// allowed.
std::string ray_problem(const Ray& ray);

constexpr uint32_t kNoHit = std::numeric_limits<uint32_t>::max();
// An any-hit query reports that something was hit, not which triangle.
constexpr uint32_t kAnyPrim = kNoHit - 1;

struct Hit {
  float t = std::numeric_limits<float>::infinity();
  float u = 0.0f, v = 0.0f;    // barycentrics of the hit point
  uint32_t prim = kNoHit;      // triangle index in the TriangleMesh (in the instance's mesh)
  uint32_t instance = kNoHit;  // instanced geometry (traces/instances.h): the instance hit
  bool hit() const { return prim != kNoHit; }
};

// Triangle geometry: what the BVH and traversal need, nothing about materials but which
// triangles are alpha-tested.
struct TriangleMesh {
  std::vector<glm::vec3> positions;
  std::vector<std::array<uint32_t, 3>> triangles;
  std::shared_ptr<const TriangleAlpha> alpha;  // null: every triangle is opaque

  size_t triangle_count() const { return triangles.size(); }
  glm::vec3 vertex(size_t tri, int corner) const { return positions[triangles[tri][corner]]; }
  std::array<glm::vec3, 3> corners(size_t tri) const {
    return {vertex(tri, 0), vertex(tri, 1), vertex(tri, 2)};
  }
};

// Hash of positions and indices: identifies a scene's geometry in ray-stream headers.
uint64_t mesh_fingerprint(const TriangleMesh& mesh);

struct Bounds {
  glm::vec3 lo{std::numeric_limits<float>::infinity()};
  glm::vec3 hi{-std::numeric_limits<float>::infinity()};
  void grow(const glm::vec3& p);
  void grow(const Bounds& b);
  bool empty() const { return lo.x > hi.x; }
  glm::vec3 extent() const { return hi - lo; }
  glm::vec3 center() const { return 0.5f * (lo + hi); }
  float surface_area() const;
};

Bounds mesh_bounds(const TriangleMesh& mesh);

}  // namespace rtsim
