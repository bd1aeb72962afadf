#include "workloads/pipeline/shading.h"

#include "workloads/pipeline/sampling.h"

namespace rtsim::pipeline {

glm::vec3 diffuse_albedo(const ShadingMaterial& m) {
  return m.base_color * (1.0f - m.metalness) * (1.0f - m.transmission);
}

glm::vec3 shade_surface(const SceneContext& scene, const Surface& s, const float* visibility) {
  const ShadingMaterial& m = scene.material_of(s.prim);
  glm::vec3 irradiance(0.0f);
  for (size_t l = 0; l < scene.lights.size(); ++l) {
    float v = visibility ? visibility[l] : 1.0f;
    if (v > 0.0f) irradiance += v * light_irradiance(scene.lights[l], s.position, s.normal);
  }
  return m.emission + diffuse_albedo(m) / kPi * irradiance;
}

}  // namespace rtsim::pipeline
