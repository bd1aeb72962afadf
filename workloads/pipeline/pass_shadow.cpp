#include "workloads/pipeline/pass_shadow.h"

#include "workloads/pipeline/rng.h"

namespace rtsim::pipeline {

PassOutcome run_shadow_pass(const FrameContext& ctx, const GBuffer& g, RaySink& sink,
                            ShadowResult& out) {
  const auto& lights = ctx.scene.lights;
  const PassRate& rate = ctx.passes.shadow;
  out.lights = uint32_t(lights.size());
  out.visibility.assign(g.samples.size() * lights.size(), -1.0f);
  if (!rate.enabled) return {"disabled in the spec"};
  if (lights.empty()) return {"no lights"};
  sink.set_pass(PassId::Shadow);
  uint64_t before = sink.count(PassId::Shadow);
  bool any_surface = false;
  auto per_sample = uint32_t(lights.size()) * rate.rays_per_pixel;
  for (uint32_t i : g.select(rate.resolution_scale, ctx.frame)) {
    const GSample& s = g.samples[i];
    if (!s.surface.hit()) continue;
    any_surface = true;
    Pcg32 rng = make_rng(ctx.seed, RngStream::Shadow, ctx.frame, i);
    for (uint32_t l = 0; l < lights.size(); ++l) {
      uint32_t shot = 0, visible = 0;
      for (uint32_t k = 0; k < rate.rays_per_pixel; ++k) {
        glm::vec2 u(rng.uniform(), rng.uniform());
        Ray ray = ctx.ray(RayType::Shadow, Query::AnyHit);
        if (!make_shadow_ray(lights[l], s.surface.position, s.surface.normal, u, ray)) continue;
        ray.pixel = s.pixel;
        ray.sample = ray_sample_id(s.index, per_sample, l * rate.rays_per_pixel + k);
        ++shot;
        visible += ctx.scene.shoot_occluded(sink, ray, s.surface.prim) ? 0 : 1;
      }
      if (shot > 0) out.visibility[size_t(i) * lights.size() + l] = float(visible) / float(shot);
    }
  }
  if (sink.count(PassId::Shadow) > before) return {};
  return {any_surface ? "no surface in view faces a light" : "no surface in view"};
}

}  // namespace rtsim::pipeline
