// Small scenes and helpers shared by the model tests.
#pragma once

#include <vector>

#include "model/bvh/bvh_image.h"
#include "model/units/traversal.h"
#include "model/verify/ray_samples.h"
#include "traces/ray.h"

namespace rtsim::test {

// Seeded soup of n triangles of size about `size` in the cube [0, 10]^3.
inline TriangleMesh random_soup(size_t n, float size, uint64_t seed) {
  SeededRandom random(seed);
  TriangleMesh mesh;
  for (size_t i = 0; i < n; ++i) {
    glm::vec3 c(10 * random.uniform(), 10 * random.uniform(), 10 * random.uniform());
    auto base = static_cast<uint32_t>(mesh.positions.size());
    for (int k = 0; k < 3; ++k) mesh.positions.push_back(c + size * random_direction(random));
    mesh.triangles.push_back({base, base + 1, base + 2});
  }
  return mesh;
}

inline void add_triangle(TriangleMesh& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
  auto base = static_cast<uint32_t>(mesh.positions.size());
  mesh.positions.push_back(a);
  mesh.positions.push_back(b);
  mesh.positions.push_back(c);
  mesh.triangles.push_back({base, base + 1, base + 2});
}

inline BvhConfig config(NodeFormat format, int width, int leaf = 3) {
  BvhConfig c;
  c.node_format = format;
  c.width = width;
  c.max_leaf_size = leaf;
  return c;
}

// AMD RDNA2/3 nodes (amd_box32, amd_box16): 4 wide, one triangle node per leaf.
inline BvhConfig amd_config(NodeFormat format) {
  BvhConfig c = config(format, 4, 1);
  c.triangle_format = TriangleFormat::AmdTriangle;
  return c;
}

// Every node format and width, compressed nodes padded to 128-byte lines, and AMD's formats.
inline std::vector<BvhConfig> all_configs() {
  std::vector<BvhConfig> out;
  for (NodeFormat f : {NodeFormat::Aabb32, NodeFormat::Cwbvh8})
    for (int w : {2, 4, 6, 8}) out.push_back(config(f, w));
  out.push_back(config(NodeFormat::Cwbvh8, 8));
  out.back().node_align = 128;
  for (NodeFormat f : {NodeFormat::AmdBox32, NodeFormat::AmdBox16}) out.push_back(amd_config(f));
  return out;
}

// A closest hit on prim at t, as EmbreeScene::trace reports it.
inline Hit hit_of(uint32_t prim, float t) {
  Hit h;
  h.prim = prim;
  h.t = t;
  return h;
}

inline Ray ray_to(glm::vec3 org, glm::vec3 target) {
  Ray r;
  r.org = org;
  r.dir = target - org;
  return r;
}

}  // namespace rtsim::test
