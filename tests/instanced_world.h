// A small instanced world for the tests of instancing (traces/, model/): a closed box mesh and a
// fan mesh placed seven times, translated, scaled, rotated, sheared, mirrored and tiny.
#pragma once

#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "traces/instances.h"

namespace rtsim::test {

// A closed box of 12 triangles, [-1,1]^3, and a fan of 8 thin triangles in the z = 0 plane.
inline TriangleMesh box_mesh() {
  TriangleMesh m;
  for (int i = 0; i < 8; ++i)
    m.positions.push_back({i & 1 ? 1.0f : -1.0f, i & 2 ? 1.0f : -1.0f, i & 4 ? 1.0f : -1.0f});
  const uint32_t faces[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                                {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
  for (const auto& f : faces) {
    m.triangles.push_back({f[0], f[1], f[2]});
    m.triangles.push_back({f[0], f[2], f[3]});
  }
  return m;
}

inline TriangleMesh fan_mesh() {
  TriangleMesh m;
  m.positions.push_back({0.0f, 0.0f, 0.0f});
  for (int i = 0; i <= 8; ++i) {
    float a = float(i) * 0.7f;
    m.positions.push_back({1.5f * std::cos(a), 1.5f * std::sin(a), 0.0f});
  }
  for (uint32_t i = 1; i <= 8; ++i) m.triangles.push_back({0, i, i + 1});
  return m;
}

inline Transform make(const glm::mat3& linear, const glm::vec3& offset) {
  Transform t;
  t.linear = linear;
  t.offset = offset;
  return t;
}

inline InstancedMesh instanced_world() {
  InstancedMesh g;
  g.meshes = {box_mesh(), fan_mesh()};
  glm::mat3 rotate =
      glm::mat3(glm::rotate(glm::mat4(1.0f), 0.65f, glm::normalize(glm::vec3(1, 2, 3))));
  glm::mat3 shear(1.0f);
  shear[1][0] = 0.4f;  // x += 0.4 y
  glm::mat3 mirror(1.0f);
  mirror[0][0] = -1.0f;
  g.instances = {
      {0, make(glm::mat3(1.0f), {0, 0, 0})},
      {0, make(glm::mat3(glm::vec3(2.0f, 0, 0), glm::vec3(0, 0.5f, 0), glm::vec3(0, 0, 3.0f)),
               {6, 0, 0})},
      {0, make(rotate * 1.5f, {-6, 1, 2})},
      {0, make(mirror * shear, {0, 6, -1})},
      {1, make(rotate, {0, -6, 0})},
      {1, make(mirror * glm::mat3(2.0f), {5, -5, 3})},
      {0, make(glm::mat3(1e-3f), {3, 3, 3})},  // tiny
  };
  return g;
}

// A ray from the box of +-15 around the world towards a random point within +-7 of its centre.
inline Ray world_ray(std::mt19937& rng) {
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  Ray ray;
  ray.org = glm::vec3(unit(rng), unit(rng), unit(rng)) * 15.0f;
  glm::vec3 target = glm::vec3(unit(rng), unit(rng), unit(rng)) * 7.0f;
  ray.dir = target - ray.org;
  return ray;
}

}  // namespace rtsim::test
