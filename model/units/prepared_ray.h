// Per-ray values that the ray-box and ray-triangle units compute once when a ray enters the
// traversal unit (the "ray setup" stage of an RT core). No timing of its own.
#pragma once

#include <cstdint>
#include <limits>
#include <glm/vec3.hpp>

#include "traces/ray.h"

namespace rtsim {

struct PreparedRay {
  glm::vec3 org{0.0f}, dir{0.0f};  // dir scaled by a power of two when extreme
  float tmin = 0.0f, tmax = 0.0f;  // in units of the scaled direction
  int t_exponent = 0;              // t of the original ray = ldexp(t here, t_exponent)
  // The farthest hit: one beyond would have t = +inf in the original ray's units (a tiny
  // direction's far hits overflow; Embree misses them). Boxes are not culled by it.
  float t_limit = std::numeric_limits<float>::infinity();
  // Ray-box unit: reciprocal direction, which box plane is entered first per axis, and the
  // origins shifted by the box padding for the near and far planes.
  glm::vec3 inv_dir{0.0f};
  int near_is_hi[3] = {0, 0, 0};
  float org_near[3] = {0, 0, 0}, org_far[3] = {0, 0, 0};
  // Ray-triangle unit (Woop, Benthin & Wald 2013): axis permutation and shear constants.
  int kx = 0, ky = 1, kz = 2;
  float sx = 0.0f, sy = 0.0f, sz = 1.0f;
};

// box_padding: how much every box grows, relative to |origin| + scene_extent (largest
// |coordinate| of the scene), so that the box test never rejects a box whose triangle the
// watertight test, computing on rounded values, would hit.
PreparedRay prepare_ray(const Ray& ray, float scene_extent, float box_padding);

}  // namespace rtsim
