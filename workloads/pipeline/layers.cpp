#include "workloads/pipeline/layers.h"

#include <algorithm>

#include "workloads/pipeline/sampling.h"

namespace rtsim::pipeline {

LayerStack layer_stack(const ShadingMaterial& m, float cos_v) {
  LayerStack s;
  s.count = std::clamp(m.layers, 1, kMaxLayers);
  float luminance = 0.2126f * m.base_color.x + 0.7152f * m.base_color.y + 0.0722f * m.base_color.z;
  float visible = 1.0f, total = 0.0f;
  for (int k = 0; k < s.count; ++k) {
    bool base = k == s.count - 1;
    float roughness = base ? m.roughness : m.coat_roughness;
    s.alpha[k] = std::max(roughness * roughness, 1e-4f);
    s.f0[k] = base ? dielectric_f0(m.ior) * (1.0f - m.metalness) + luminance * m.metalness
                   : dielectric_f0(m.ior);
    float fresnel = schlick(s.f0[k], cos_v);
    s.probability[k] = visible * fresnel;
    total += s.probability[k];
    visible *= 1.0f - fresnel;
  }
  for (int k = 0; k < s.count; ++k)
    s.probability[k] = total > 0.0f ? s.probability[k] / total : (k == 0 ? 1.0f : 0.0f);
  return s;
}

int choose_layer(const LayerStack& stack, float u) {
  float cumulative = 0.0f;
  for (int k = 0; k < stack.count; ++k) {
    cumulative += stack.probability[k];
    if (u < cumulative) return k;
  }
  return stack.count - 1;
}

float stack_pdf(const LayerStack& stack, const glm::vec3& v, const glm::vec3& l) {
  float pdf = 0.0f;
  for (int k = 0; k < stack.count; ++k)
    pdf += stack.probability[k] * ggx_reflection_pdf(v, l, stack.alpha[k]);
  return pdf;
}

}  // namespace rtsim::pipeline
