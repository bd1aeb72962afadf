#include "workloads/pipeline/pass_translucency.h"

#include <glm/geometric.hpp>

#include "workloads/pipeline/offset.h"
#include "workloads/pipeline/rng.h"
#include "workloads/pipeline/sampling.h"
#include "workloads/pipeline/shading.h"

namespace rtsim::pipeline {

PassOutcome run_translucency_pass(const FrameContext& ctx, const GBuffer& g, RaySink& sink,
                                  TranslucencyResult& out) {
  const PassRate& spec = ctx.passes.translucency;
  out = {};
  if (!spec.enabled) return {"disabled in the spec"};
  sink.set_pass(PassId::Translucency);
  for (uint32_t i : g.select(spec.resolution_scale, ctx.frame)) {
    const GSample& s = g.samples[i];
    if (!s.surface.hit() || ctx.scene.materials.materials[s.material].translucency <= 0.0f)
      continue;
    glm::vec3 inward = -s.surface.normal;
    Pcg32 rng = make_rng(ctx.seed, RngStream::Translucency, ctx.frame, i);
    glm::vec3 sum(0.0f);
    for (uint32_t k = 0; k < spec.rays_per_pixel; ++k) {
      glm::vec3 d = sample_uniform_sphere(glm::vec2(rng.uniform(), rng.uniform()));
      if (glm::dot(d, inward) < 0.0f) d = reflect_dir(d, inward);
      Ray ray = ctx.ray(RayType::Translucency, Query::ClosestHit);
      ray.org = offset_ray_origin(s.surface.position, inward);
      ray.dir = glm::normalize(d);
      ray.pixel = s.pixel;
      ray.sample = ray_sample_id(s.index, spec.rays_per_pixel, k);
      Surface hit = ctx.scene.shoot_surface(sink, ray, s.surface.prim);
      if (!hit.hit()) {
        sum += ctx.scene.sky;
        continue;
      }
      // Light arriving at the far side from outside: shade with the outward normal.
      hit.normal = -hit.normal;
      sum += shade_surface(ctx.scene, hit, nullptr);
    }
    out.samples.push_back(i);
    out.radiance.push_back(sum / float(spec.rays_per_pixel));
  }
  if (out.samples.empty()) return {"no translucent surface in view"};
  return {};
}

}  // namespace rtsim::pipeline
