#include "traces/ray.h"

#include <cmath>
#include <cstring>

#include <glm/common.hpp>

#include "traces/hash.h"

namespace rtsim {
namespace {

constexpr const char* kRayTypeNames[kRayTypeCount] = {
    "camera",     "shadow", "reflection", "reflected_shadow",
    "diffuse_gi", "ao",     "refraction", "translucency"};

bool finite3(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool in_range(const glm::vec3& v) {
  return std::fabs(v.x) <= kMaxRayComponent && std::fabs(v.y) <= kMaxRayComponent &&
         std::fabs(v.z) <= kMaxRayComponent;
}

}  // namespace

const char* ray_type_name(RayType type) {
  auto i = static_cast<int>(type);
  return i < kRayTypeCount ? kRayTypeNames[i] : "invalid";
}

std::optional<RayType> ray_type_from_name(const std::string& name) {
  for (int i = 0; i < kRayTypeCount; ++i)
    if (name == kRayTypeNames[i]) return static_cast<RayType>(i);
  return std::nullopt;
}

const char* query_name(Query query) {
  return query == Query::AnyHit ? "any_hit" : "closest_hit";
}

bool Ray::operator==(const Ray& o) const {
  // Bitwise: -0 and +0 differ, as they do in the file.
  auto same = [](const void* a, const void* b, size_t n) { return std::memcmp(a, b, n) == 0; };
  return same(&org, &o.org, sizeof org) && same(&dir, &o.dir, sizeof dir) &&
         same(&tmin, &o.tmin, sizeof tmin) && same(&tmax, &o.tmax, sizeof tmax) && type == o.type &&
         query == o.query && force_opaque == o.force_opaque && sample == o.sample &&
         pixel == o.pixel && frame == o.frame;
}

std::string ray_problem(const Ray& ray) {
  if (!finite3(ray.org)) return "origin is NaN or Inf";
  if (!finite3(ray.dir)) return "direction is NaN or Inf";
  if (!in_range(ray.org)) return "an origin component is beyond +-1.844e18 (Embree's range)";
  if (!in_range(ray.dir)) return "a direction component is beyond +-1.844e18 (Embree's range)";
  if (ray.dir.x == 0.0f && ray.dir.y == 0.0f && ray.dir.z == 0.0f) return "direction is zero";
  if (!std::isfinite(ray.tmin)) return "tmin is NaN or Inf";
  if (std::isnan(ray.tmax) || ray.tmax == -std::numeric_limits<float>::infinity())
    return "tmax is NaN or -Inf";
  if (ray.tmin < 0.0f) return "tmin is negative";
  if (ray.tmin > ray.tmax) return "tmin is greater than tmax";
  if (static_cast<int>(ray.type) >= kRayTypeCount) return "unknown ray type";
  if (static_cast<int>(ray.query) > 1) return "unknown query";
  return {};
}

uint64_t mesh_fingerprint(const TriangleMesh& mesh) {
  uint64_t n[2] = {mesh.positions.size(), mesh.triangles.size()};
  uint64_t h = fnv1a64(n, sizeof n);
  h = fnv1a64(mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3), h);
  h = fnv1a64(mesh.triangles.data(), mesh.triangles.size() * sizeof(mesh.triangles[0]), h);
  if (!mesh.alpha) return h;
  // Alpha-tested triangles decide hits too: their masks, cutoffs and coordinates.
  const TriangleAlpha& a = *mesh.alpha;
  h = fnv1a64(a.mask_of.data(), a.mask_of.size() * sizeof(uint32_t), h);
  h = fnv1a64(a.uv.data(), a.uv.size() * sizeof(a.uv[0]), h);
  for (const auto& m : a.masks) {
    h = fnv1a64(&m->cutoff, sizeof m->cutoff, h);
    uint32_t size[2] = {m->width, m->height};
    h = fnv1a64(size, sizeof size, h);
    h = fnv1a64(m->alpha.data(), m->alpha.size(), h);
  }
  return h;
}

void Bounds::grow(const glm::vec3& p) {
  lo = glm::min(lo, p);
  hi = glm::max(hi, p);
}

void Bounds::grow(const Bounds& b) {
  lo = glm::min(lo, b.lo);
  hi = glm::max(hi, b.hi);
}

float Bounds::surface_area() const {
  if (empty()) return 0.0f;
  glm::vec3 e = extent();
  return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
}

Bounds mesh_bounds(const TriangleMesh& mesh) {
  Bounds b;
  for (const auto& p : mesh.positions) b.grow(p);
  return b;
}

}  // namespace rtsim
