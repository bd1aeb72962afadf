#include "workloads/pipeline/offset.h"

#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>

namespace rtsim::pipeline {
namespace {

// Constants from the paper: below kOrigin use a float offset, else an integer ulp offset.
constexpr float kOrigin = 1.0f / 32.0f;
constexpr float kFloatScale = 1.0f / 65536.0f;
constexpr float kIntScale = 256.0f;

float offset_coordinate(float p, float n) {
  auto of_i = static_cast<int32_t>(kIntScale * n);
  int32_t bits;
  std::memcpy(&bits, &p, sizeof bits);
  bits += p < 0.0f ? -of_i : of_i;
  float p_i;
  std::memcpy(&p_i, &bits, sizeof p_i);
  return std::fabs(p) < kOrigin ? p + kFloatScale * n : p_i;
}

}  // namespace

glm::vec3 hit_point(const std::array<glm::vec3, 3>& corners, float u, float v) {
  const glm::vec3 &v0 = corners[0], &v1 = corners[1], &v2 = corners[2];
  return v0 + u * (v1 - v0) + v * (v2 - v0);
}

glm::vec3 face_normal(const std::array<glm::vec3, 3>& corners) {
  // In double: the cross product of tiny edges underflows in float.
  glm::dvec3 v0 = corners[0], v1 = corners[1], v2 = corners[2];
  glm::dvec3 n = glm::cross(v1 - v0, v2 - v0);
  double len = glm::length(n);
  return len > 0.0 && std::isfinite(len) ? glm::vec3(n / len) : glm::vec3(0.0f);
}

glm::vec3 offset_ray_origin(const glm::vec3& p, const glm::vec3& n) {
  return glm::vec3(offset_coordinate(p.x, n.x), offset_coordinate(p.y, n.y),
                   offset_coordinate(p.z, n.z));
}

}  // namespace rtsim::pipeline
