// What every pass sees: the scene with its materials and lights (fixed for a run), the frame
// (camera, index, seed), and the surface found by a closest hit.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "traces/embree_scene.h"
#include "traces/ray.h"
#include "workloads/pipeline/camera.h"
#include "workloads/pipeline/lights.h"
#include "workloads/pipeline/materials.h"
#include "workloads/pipeline/spec.h"
#include "workloads/scene.h"

namespace rtsim::pipeline {

struct Surface;
class RaySink;

struct SceneContext {
  const Scene& scene;
  const MaterialTable& materials;
  const EmbreeScene& embree;  // over the scene's flattened mesh, or over its instances
  std::vector<Light> lights;
  glm::vec3 sky{0.0f};
  float diagonal = 1.0f;           // length of the scene bounds' diagonal
  bool emission_is_light = false;  // emissive objects were turned into lights

  const ShadingMaterial& material_of(uint32_t prim) const { return materials.of(prim); }
  // Embree's closest hit, its triangle named by flat id; met_alpha as EmbreeScene::intersect's.
  Hit intersect(const Ray& ray, bool* met_alpha = nullptr) const {
    return materials.triangles.flat(embree.intersect(ray, met_alpha));
  }

  // A pass's ray, traced and put into the sink (under its current pass) with whether it met an
  // alpha-tested candidate; origin_prim as RaySink::emit takes it.
  Hit shoot_closest(RaySink& sink, const Ray& ray, uint32_t origin_prim = kNoHit) const;
  Surface shoot_surface(RaySink& sink, const Ray& ray, uint32_t origin_prim) const;
  bool shoot_occluded(RaySink& sink, const Ray& ray, uint32_t origin_prim) const;
};

struct FrameContext {
  const SceneContext& scene;
  const PassSpecs& passes;
  Camera camera;
  uint32_t frame = 0;
  uint64_t seed = 0;
  uint32_t width = 1, height = 1;

  // A ray of this frame of the given type and query, forced opaque where the spec's
  // [alpha_test] turns its type's alpha test off.
  Ray ray(RayType type, Query query) const {
    Ray r;
    r.type = type;
    r.query = query;
    r.force_opaque = !passes.alpha_test[size_t(type)];
    r.frame = frame;
    return r;
  }
};

// A surface point found by a ray: the hit point from the triangle's barycentrics and the unit
// geometric normal turned toward the ray's origin (front: the ray hit the side the winding
// order faces).
struct Surface {
  glm::vec3 position{0.0f}, normal{0.0f, 1.0f, 0.0f};
  uint32_t prim = kNoHit;
  bool front = true;
  bool hit() const { return prim != kNoHit; }
};

// The surface of a hit named by flat id.
Surface surface_at(const FlatTriangles& triangles, const Ray& ray, const Hit& hit);

// What a pass did: if it shot nothing, why (for the run summary).
struct PassOutcome {
  std::string skipped;
};

// The `sample` field of the j-th ray a pass shoots for camera sample `index` when it shoots
// `per_sample` rays per camera sample.
inline uint16_t ray_sample_id(uint16_t index, uint32_t per_sample, uint32_t j) {
  return uint16_t(uint32_t(index) * per_sample + j);
}

}  // namespace rtsim::pipeline
