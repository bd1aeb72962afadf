#include "workloads/pipeline/pass_reflected_shadow.h"

#include "workloads/pipeline/rng.h"

namespace rtsim::pipeline {

PassOutcome run_reflected_shadow_pass(const FrameContext& ctx, const GBuffer& g,
                                      const ReflectionResult& reflections, RaySink& sink,
                                      ReflectedShadowResult& out) {
  const auto& lights = ctx.scene.lights;
  out.lights = uint32_t(lights.size());
  out.visibility.assign(reflections.rays.size() * lights.size(), -1.0f);
  if (!ctx.passes.reflected_shadow) return {"disabled in the spec"};
  if (lights.empty()) return {"no lights"};
  if (reflections.rays.empty()) return {"no reflection rays"};
  sink.set_pass(PassId::ReflectedShadow);
  uint64_t before = sink.count(PassId::ReflectedShadow);
  bool any_hit = false;
  auto per_sample = uint32_t(lights.size());
  for (size_t r = 0; r < reflections.rays.size(); ++r) {
    const ReflectionRecord& rec = reflections.rays[r];
    if (!rec.hit.hit()) continue;
    any_hit = true;
    const GSample& s = g.samples[rec.sample];
    Pcg32 rng = make_rng(ctx.seed, RngStream::ReflectedShadow, ctx.frame, r);
    for (uint32_t l = 0; l < lights.size(); ++l) {
      glm::vec2 u(rng.uniform(), rng.uniform());
      Ray ray = ctx.ray(RayType::ReflectedShadow, Query::AnyHit);
      if (!make_shadow_ray(lights[l], rec.hit.position, rec.hit.normal, u, ray)) continue;
      ray.pixel = s.pixel;
      ray.sample = ray_sample_id(s.index, per_sample, l);
      bool occluded = ctx.scene.shoot_occluded(sink, ray, rec.hit.prim);
      out.visibility[r * lights.size() + l] = occluded ? 0.0f : 1.0f;
    }
  }
  if (sink.count(PassId::ReflectedShadow) > before) return {};
  return {any_hit ? "no reflection hit faces a light" : "every reflection ray escaped"};
}

}  // namespace rtsim::pipeline
