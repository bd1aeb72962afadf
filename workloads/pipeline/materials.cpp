#include "workloads/pipeline/materials.h"

#include <map>
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
  // A triangle's result depends only on its (material, object) pair.
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> made;
  table.of_triangle.resize(scene.triangle_count());
  for (size_t tri = 0; tri < scene.triangle_count(); ++tri) {
    uint32_t mat = tri < scene.material_ids.size() ? scene.material_ids[tri] : 0;
    uint32_t obj = tri < scene.object_ids.size() ? scene.object_ids[tri] : 0;
    auto key = std::make_pair(mat, obj);
    auto found = made.find(key);
    if (found != made.end()) {
      table.of_triangle[tri] = found->second;
      continue;
    }
    ShadingMaterial m =
        mat < scene.materials.size() ? from_scene(scene.materials[mat]) : ShadingMaterial{};
    const std::string object = obj < scene.object_names.size() ? scene.object_names[obj] : "";
    for (const MaterialRule& rule : rules)
      if (glob_match(rule.match, object) || glob_match(rule.match, m.name)) apply(rule, m);
    auto id = static_cast<uint32_t>(table.materials.size());
    table.materials.push_back(m);
    made.emplace(key, id);
    table.of_triangle[tri] = id;
  }
  if (table.materials.empty()) table.materials.emplace_back();
  return table;
}

}  // namespace rtsim::pipeline
