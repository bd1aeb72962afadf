// The materials the passes shade with: the scene's materials with the spec's rules applied.
// A rule matches a triangle by its object (group) name or its material name; rules apply in
// order, and unset fields keep the previous value.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <unordered_map>
#include <vector>

#include "workloads/pipeline/spec.h"
#include "workloads/scene.h"

namespace rtsim::pipeline {

struct ShadingMaterial {
  std::string name;
  glm::vec3 base_color{0.8f};
  float roughness = 0.5f;
  float metalness = 0.0f;
  int layers = 1;  // 1 + clear coats over the base
  float coat_roughness = 0.05f;
  float transmission = 0.0f;
  float ior = 1.5f;
  float translucency = 0.0f;
  glm::vec3 emission{0.0f};

  // Has a lobe sharp enough for a reflection ray: the base or any coat.
  bool glossy(float max_roughness) const {
    return roughness <= max_roughness || (layers > 1 && coat_roughness <= max_roughness);
  }
  bool emissive() const { return emission.x > 0.0f || emission.y > 0.0f || emission.z > 0.0f; }
};

// One shading material per (scene material, object) pair the scene uses. A flattened scene's
// triangles find theirs in a per-triangle array; an unflattened one's through their instance.
struct MaterialTable {
  std::vector<ShadingMaterial> materials;
  std::vector<uint32_t> of_triangle;               // flattened scenes: index per triangle
  std::unordered_map<uint64_t, uint32_t> of_pair;  // object << 32 | material -> index
  const Scene* scene = nullptr;
  FlatTriangles triangles;  // the scene's

  uint32_t index_of(TriangleAttributes a) const {
    return of_pair.at(uint64_t(a.object) << 32 | a.material);
  }
  uint32_t index_of(uint32_t prim) const {
    return of_triangle.empty() ? index_of(scene->attributes(triangles, prim)) : of_triangle[prim];
  }
  const ShadingMaterial& of(uint32_t prim) const { return materials[index_of(prim)]; }
  bool any_emissive() const;
};

MaterialTable assign_materials(const Scene& scene, const std::vector<MaterialRule>& rules);

// Shell-style glob: * any run, ? any one character; case-sensitive.
bool glob_match(const std::string& pattern, const std::string& text);

}  // namespace rtsim::pipeline
