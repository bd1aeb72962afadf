#include "workloads/pipeline/pass_reflection.h"

#include <glm/geometric.hpp>

#include "workloads/pipeline/offset.h"
#include "workloads/pipeline/rng.h"
#include "workloads/pipeline/sampling.h"

namespace rtsim::pipeline {

glm::vec3 sample_reflection(const LayerStack& stack, int layer, const glm::vec3& v,
                            const glm::vec3& n, uint32_t index, glm::vec2 rotation,
                            uint32_t max_rerolls, uint32_t& rerolls) {
  Basis basis(n);
  glm::vec3 v_local = basis.to_local(v);
  rerolls = 0;
  for (uint32_t attempt = 0; attempt <= max_rerolls; ++attempt) {
    // Re-rolls jump far along the sequence (a prime stride), away from later frames' points.
    uint32_t i = index + attempt * 1000003u;
    glm::vec2 u = cranley_patterson(glm::vec2(halton(i, 2), halton(i, 3)), rotation);
    glm::vec3 h = sample_ggx_half_vector(u, stack.alpha[layer]);
    glm::vec3 l = reflect_dir(-v_local, h);
    if (l.z > 0.0f) return glm::normalize(basis.to_world(l));
    ++rerolls;
  }
  return glm::normalize(reflect_dir(-v, n));
}

PassOutcome run_reflection_pass(const FrameContext& ctx, const GBuffer& g, RaySink& sink,
                                ReflectionResult& out) {
  const ReflectionSpec& spec = ctx.passes.reflection;
  out.rays.clear();
  if (!spec.enabled) return {"disabled in the spec"};
  sink.set_pass(PassId::Reflection);
  bool any_surface = false;
  for (uint32_t i : g.select(spec.resolution_scale, ctx.frame)) {
    const GSample& s = g.samples[i];
    if (!s.surface.hit()) continue;
    any_surface = true;
    const ShadingMaterial& m = ctx.scene.materials.materials[s.material];
    if (!m.glossy(spec.max_roughness)) continue;
    glm::vec3 v = -s.view;
    LayerStack stack = layer_stack(m, glm::dot(v, s.surface.normal));
    Pcg32 rng = make_rng(ctx.seed, RngStream::Reflection, ctx.frame, i);
    Pcg32 rot_rng = make_rng(ctx.seed, RngStream::ReflectionRotation, 0, s.pixel);
    glm::vec2 rotation(rot_rng.uniform(), rot_rng.uniform());
    for (uint32_t j = 0; j < spec.rays_per_pixel; ++j) {
      ReflectionRecord rec;
      rec.sample = i;
      rec.layer = uint8_t(choose_layer(stack, rng.uniform()));
      // Consecutive frames take consecutive Halton points, so each pixel's directions over
      // time are stratified.
      uint32_t index = 1 + ctx.frame * spec.rays_per_pixel + j;
      uint32_t rerolls = 0;
      rec.dir = sample_reflection(stack, rec.layer, v, s.surface.normal, index, rotation,
                                  spec.max_rerolls, rerolls);
      rec.rerolls = uint8_t(rerolls);
      Basis basis(s.surface.normal);
      rec.pdf = stack_pdf(stack, basis.to_local(v), basis.to_local(rec.dir));
      Ray ray = ctx.ray(RayType::Reflection, Query::ClosestHit);
      ray.org = offset_ray_origin(s.surface.position, s.surface.normal);
      ray.dir = rec.dir;
      ray.pixel = s.pixel;
      ray.sample = ray_sample_id(s.index, spec.rays_per_pixel, j);
      rec.hit = ctx.scene.shoot_surface(sink, ray, s.surface.prim);
      out.rays.push_back(rec);
    }
  }
  if (!out.rays.empty()) return {};
  return {any_surface ? "no glossy surface in view (roughness <= reflection.max_roughness)"
                      : "no surface in view"};
}

}  // namespace rtsim::pipeline
