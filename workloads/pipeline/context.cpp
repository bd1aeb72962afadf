#include "workloads/pipeline/context.h"

#include <glm/geometric.hpp>

#include "workloads/pipeline/offset.h"

namespace rtsim::pipeline {

Surface surface_at(const FlatTriangles& triangles, const Ray& ray, const Hit& hit) {
  Surface s;
  if (!hit.hit() || hit.prim == kAnyPrim) return s;
  s.prim = hit.prim;
  std::array<glm::vec3, 3> corners = triangles.corners(hit.prim, ray.frame);
  s.position = hit_point(corners, hit.u, hit.v);
  glm::vec3 n = face_normal(corners);
  if (n == glm::vec3(0.0f)) n = -glm::normalize(ray.dir);  // degenerate: face the ray
  s.front = glm::dot(n, ray.dir) <= 0.0f;
  s.normal = s.front ? n : -n;
  return s;
}

Surface SceneContext::surface(const Ray& ray) const {
  return surface_at(materials.triangles, ray, intersect(ray));
}

}  // namespace rtsim::pipeline
