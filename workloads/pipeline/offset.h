// Robust secondary-ray origins: "A Fast and Robust Method for Avoiding Self-Intersection"
// (Carsten Wächter, Nikolaus Binder; Ray Tracing Gems, chapter 6, 2019). The hit point is
// computed from the triangle's vertices and barycentrics, then moved along the geometric normal
// by a few units in the last place of each coordinate (a fixed tiny distance near the origin,
// where ulps vanish), so float error never leaves a secondary ray behind its own triangle.
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>

#include "traces/ray.h"

namespace rtsim::pipeline {

// Hit point on a triangle at barycentrics (u, v): v0 + u (v1 - v0) + v (v2 - v0).
glm::vec3 hit_point(const std::array<glm::vec3, 3>& corners, float u, float v);

// Unit geometric normal (v1 - v0) x (v2 - v0); zero for a degenerate triangle.
glm::vec3 face_normal(const std::array<glm::vec3, 3>& corners);

// p moved off the surface along n (unit, pointing to the side the new ray leaves from).
glm::vec3 offset_ray_origin(const glm::vec3& p, const glm::vec3& n);

}  // namespace rtsim::pipeline
