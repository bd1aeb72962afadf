#include "workloads/pipeline/pass_ao.h"

#include <glm/geometric.hpp>

#include "workloads/pipeline/offset.h"
#include "workloads/pipeline/rng.h"
#include "workloads/pipeline/sampling.h"

namespace rtsim::pipeline {

float ao_radius(const FrameContext& ctx) {
  return ctx.passes.ao.radius.value_or(0.02f * ctx.scene.diagonal);
}

PassOutcome run_ao_pass(const FrameContext& ctx, const GBuffer& g, RaySink& sink, AoResult& out) {
  const AoSpec& spec = ctx.passes.ao;
  out = {};
  if (!spec.enabled) return {"disabled in the spec"};
  float radius = ao_radius(ctx);
  if (!(radius > 0.0f)) return {"radius is 0"};
  sink.set_pass(PassId::AO);
  for (uint32_t i : g.select(spec.resolution_scale, ctx.frame)) {
    const GSample& s = g.samples[i];
    if (!s.surface.hit()) continue;
    Basis basis(s.surface.normal);
    Pcg32 rng = make_rng(ctx.seed, RngStream::AO, ctx.frame, i);
    uint32_t open = 0;
    for (uint32_t k = 0; k < spec.rays_per_pixel; ++k) {
      Ray ray = ctx.ray(RayType::AO, Query::AnyHit);
      ray.org = offset_ray_origin(s.surface.position, s.surface.normal);
      ray.dir = glm::normalize(
          basis.to_world(sample_cosine_hemisphere(glm::vec2(rng.uniform(), rng.uniform()))));
      ray.tmax = radius;
      ray.pixel = s.pixel;
      ray.sample = ray_sample_id(s.index, spec.rays_per_pixel, k);
      open += ctx.scene.shoot_occluded(sink, ray, s.surface.prim) ? 0 : 1;
    }
    out.samples.push_back(i);
    out.visibility.push_back(float(open) / float(spec.rays_per_pixel));
  }
  if (out.samples.empty()) return {"no surface in view"};
  return {};
}

}  // namespace rtsim::pipeline
