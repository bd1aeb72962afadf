// Lights resolved for one scene (auto positions and radii filled, emissive objects turned into
// spherical lights), and the shadow rays toward them. Soft shadows from a spherical light
// sample a uniform cone of directions toward the sphere (PBRT 3rd ed., 14.2.2), so the cone
// width sets the penumbra; point and spot lights give hard shadows.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "traces/ray.h"
#include "workloads/pipeline/materials.h"
#include "workloads/pipeline/spec.h"
#include "workloads/scene.h"

namespace rtsim::pipeline {

struct Light {
  LightType type = LightType::Point;
  glm::vec3 position{0.0f};
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // unit; where a spot or directional light shines
  glm::vec3 intensity{1.0f};               // colour x intensity
  float radius = 0.0f;                     // sphere lights
  float cos_cone = -1.0f;                  // spot: cosine of the half angle
  float cos_sun = 1.0f;                    // directional: cosine of half the angular diameter
};

std::vector<Light> resolve_lights(const WorkloadSpec& spec, const Scene& scene,
                                  const MaterialTable& materials);

// Surface point p with unit normal n (facing where the ray leaves). Fills a shadow ray toward
// the light from the robust origin (see offset.h) and returns true, or returns false when the
// light cannot reach p: behind the surface, outside a spot cone, zero intensity, or p inside a
// spherical light.
bool make_shadow_ray(const Light& light, const glm::vec3& p, const glm::vec3& n, glm::vec2 u,
                     Ray& ray);

// Unshadowed irradiance at p with normal n from the light's centre (for preview shading).
glm::vec3 light_irradiance(const Light& light, const glm::vec3& p, const glm::vec3& n);

}  // namespace rtsim::pipeline
