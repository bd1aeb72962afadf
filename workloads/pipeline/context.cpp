#include "workloads/pipeline/context.h"

#include <glm/geometric.hpp>

#include "workloads/pipeline/offset.h"
#include "workloads/pipeline/ray_sink.h"

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

Hit SceneContext::shoot_closest(RaySink& sink, const Ray& ray, uint32_t origin_prim) const {
  bool met_alpha = false;
  Hit hit = intersect(ray, &met_alpha);
  sink.emit(ray, origin_prim, met_alpha);
  return hit;
}

Surface SceneContext::shoot_surface(RaySink& sink, const Ray& ray, uint32_t origin_prim) const {
  return surface_at(materials.triangles, ray, shoot_closest(sink, ray, origin_prim));
}

bool SceneContext::shoot_occluded(RaySink& sink, const Ray& ray, uint32_t origin_prim) const {
  bool met_alpha = false;
  bool occluded = embree.occluded(ray, &met_alpha);
  sink.emit(ray, origin_prim, met_alpha);
  return occluded;
}

}  // namespace rtsim::pipeline
