// Simple shading for pictures and GI estimates: Lambertian direct light from the pass's own
// shadow-ray results, plus emission. Not part of the ray streams; the preview and the surfel
// irradiance use it so a person can see what the rays found.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>

#include "workloads/pipeline/context.h"

namespace rtsim::pipeline {

// Diffuse albedo: base colour, darkened by metalness.
glm::vec3 diffuse_albedo(const ShadingMaterial& m);

// Radiance leaving surface s toward the viewer: emission + albedo / pi * irradiance, where
// irradiance is sum over lights of light_irradiance x visibility[l] (visibility < 0: no ray was
// shot, the light does not reach s). visibility may be null (unshadowed).
glm::vec3 shade_surface(const SceneContext& scene, const Surface& s, const float* visibility);

}  // namespace rtsim::pipeline
