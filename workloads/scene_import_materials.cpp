// Maps assimp materials onto rtsim::Material. glTF 2.0 metallic-roughness values are taken as
// they are; OBJ/MTL Phong values are converted: Ns to roughness through the Blinn-Phong to
// Beckmann/GGX equivalence alpha = sqrt(2 / (Ns + 2)) (Walter et al. 2007) unless Pr is given,
// d (opacity) to transmission = 1 - d, Ni to ior, Ke to emission.
#include <algorithm>
#include <cmath>

#include <assimp/material.h>

#include "workloads/scene_import.h"

namespace rtsim {
namespace {

bool get_color(const aiMaterial& m, const char* key, unsigned type, unsigned index,
               glm::vec3& out) {
  aiColor3D c;
  if (m.Get(key, type, index, c) != AI_SUCCESS) return false;
  out = glm::vec3(c.r, c.g, c.b);
  return true;
}

bool get_float(const aiMaterial& m, const char* key, unsigned type, unsigned index, float& out) {
  ai_real v;
  if (m.Get(key, type, index, v) != AI_SUCCESS || !std::isfinite(v)) return false;
  out = float(v);
  return true;
}

bool is_black(const glm::vec3& c) {
  return c.x <= 0.0f && c.y <= 0.0f && c.z <= 0.0f;
}

}  // namespace

Material material_from_assimp(const aiMaterial& m) {
  Material out;
  aiString name;
  if (m.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) out.name = name.C_Str();

  glm::vec3 diffuse(0.0f), specular(0.0f);
  bool pbr = get_color(m, AI_MATKEY_BASE_COLOR, out.base_color);
  if (!pbr && get_color(m, AI_MATKEY_COLOR_DIFFUSE, diffuse)) out.base_color = diffuse;
  // A Phong material with black Kd and coloured Ks (a polished block) reads as a metal.
  if (!pbr && is_black(diffuse) && get_color(m, AI_MATKEY_COLOR_SPECULAR, specular) &&
      !is_black(specular)) {
    out.base_color = specular;
    out.metalness = 1.0f;
  }

  float shininess = 0.0f;
  if (!get_float(m, AI_MATKEY_ROUGHNESS_FACTOR, out.roughness) &&
      get_float(m, AI_MATKEY_SHININESS, shininess)) {
    // roughness^2 = GGX alpha = sqrt(2 / (Ns + 2)).
    out.roughness = std::sqrt(std::sqrt(2.0f / (std::max(shininess, 0.0f) + 2.0f)));
  }
  get_float(m, AI_MATKEY_METALLIC_FACTOR, out.metalness);

  float opacity = 1.0f, transmission = 0.0f;
  get_float(m, AI_MATKEY_OPACITY, opacity);
  get_float(m, AI_MATKEY_TRANSMISSION_FACTOR, transmission);
  out.transmission = std::max(transmission, 1.0f - opacity);
  get_float(m, AI_MATKEY_REFRACTI, out.ior);

  float clear_coat = 0.0f;
  if (get_float(m, AI_MATKEY_CLEARCOAT_FACTOR, clear_coat) && clear_coat > 0.0f) out.layers = 2;

  glm::vec3 emission(0.0f);
  float intensity = 1.0f;
  if (get_color(m, AI_MATKEY_COLOR_EMISSIVE, emission)) {
    get_float(m, AI_MATKEY_EMISSIVE_INTENSITY, intensity);
    out.emission = emission * intensity;
  }

  out.roughness = std::clamp(out.roughness, 0.0f, 1.0f);
  out.metalness = std::clamp(out.metalness, 0.0f, 1.0f);
  out.transmission = std::clamp(out.transmission, 0.0f, 1.0f);
  return out;
}

}  // namespace rtsim
