#include "workloads/pipeline/materials.h"

#include <algorithm>
#include <set>
#include <utility>

namespace rtsim::pipeline {
namespace {

ShadingMaterial from_scene(const Material& m) {
  ShadingMaterial s;
  s.name = m.name;
  s.base_color = m.base_color;
  s.roughness = m.roughness;
  s.metalness = m.metalness;
  s.layers = m.layers;
  s.transmission = m.transmission;
  s.ior = m.ior;
  s.translucency = m.translucency;
  s.emission = m.emission;
  return s;
}

void apply(const MaterialRule& r, ShadingMaterial& m) {
  if (r.base_color) m.base_color = *r.base_color;
  if (r.roughness) m.roughness = *r.roughness;
  if (r.metalness) m.metalness = *r.metalness;
  if (r.layers) m.layers = *r.layers;
  if (r.coat_roughness) m.coat_roughness = *r.coat_roughness;
  if (r.transmission) m.transmission = *r.transmission;
  if (r.ior) m.ior = *r.ior;
  if (r.translucency) m.translucency = *r.translucency;
  if (r.emission) m.emission = *r.emission;
}

}  // namespace

bool glob_match(const std::string& pattern, const std::string& text) {
  size_t p = 0, t = 0, star = std::string::npos, resume = 0;
  while (t < text.size()) {
    if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == text[t])) {
      ++p;
      ++t;
    } else if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      resume = t;
    } else if (star != std::string::npos) {
      p = star + 1;
      t = ++resume;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

MaterialTable assign_materials(const Scene& scene, const std::vector<MaterialRule>& rules) {
  MaterialTable table;
  table.scene = &scene;
  table.triangles = scene.triangles();
  // A triangle's result depends only on its (material, object) pair.
  auto resolve = [&](TriangleAttributes a) {
    auto [found, inserted] =
        table.of_pair.try_emplace(uint64_t(a.object) << 32 | a.material, table.materials.size());
    if (!inserted) return found->second;
    ShadingMaterial m = a.material < scene.materials.size()
                            ? from_scene(scene.materials[a.material])
                            : ShadingMaterial{};
    const std::string object =
        a.object < scene.object_names.size() ? scene.object_names[a.object] : "";
    for (const MaterialRule& rule : rules)
      if (glob_match(rule.match, object) || glob_match(rule.match, m.name)) apply(rule, m);
    table.materials.push_back(m);
    return found->second;
  };
  if (scene.flattened()) {
    table.of_triangle.resize(scene.triangle_count());
    for (uint64_t tri = 0; tri < scene.triangle_count(); ++tri)
      table.of_triangle[tri] = resolve(scene.attributes(table.triangles, tri));
  } else {
    // Each instance's object with its material, or each material its mesh uses.
    std::vector<std::set<uint32_t>> used(scene.mesh_material_ids.size());
    for (size_t m = 0; m < used.size(); ++m)
      used[m].insert(scene.mesh_material_ids[m].begin(), scene.mesh_material_ids[m].end());
    for (size_t i = 0; i < scene.instanced.instances.size(); ++i) {
      if (uint32_t own = scene.own_material(i); own != Scene::kMeshMaterials)
        resolve({own, scene.instance_object_ids[i]});
      else
        for (uint32_t material : used[scene.instanced.instances[i].mesh])
          resolve({material, scene.instance_object_ids[i]});
    }
  }
  if (table.materials.empty()) table.materials.emplace_back();
  return table;
}

bool MaterialTable::any_emissive() const {
  return std::any_of(materials.begin(), materials.end(),
                     [](const ShadingMaterial& m) { return m.emissive(); });
}

}  // namespace rtsim::pipeline
