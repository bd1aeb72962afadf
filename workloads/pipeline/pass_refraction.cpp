#include "workloads/pipeline/pass_refraction.h"

#include <glm/geometric.hpp>

#include "workloads/pipeline/offset.h"
#include "workloads/pipeline/rng.h"
#include "workloads/pipeline/sampling.h"

namespace rtsim::pipeline {
namespace {

// The ray leaving interface `at` for a ray arriving along `incident`.
Ray next_ray(const FrameContext& ctx, const Surface& at, const ShadingMaterial& m,
             const glm::vec3& incident, glm::vec2 u) {
  float alpha = std::max(m.roughness * m.roughness, 1e-4f);
  glm::vec3 h = Basis(at.normal).to_world(sample_ggx_half_vector(u, alpha));
  if (glm::dot(h, -incident) <= 0.0f) h = at.normal;
  float eta = at.front ? 1.0f / m.ior : m.ior;
  Ray ray = ctx.ray(RayType::Refraction, Query::ClosestHit);
  glm::vec3 dir;
  if (refract_dir(incident, h, eta, dir) && glm::dot(dir, at.normal) < 0.0f) {
    ray.org = offset_ray_origin(at.position, -at.normal);
  } else {
    dir = reflect_dir(incident, h);
    if (glm::dot(dir, at.normal) <= 0.0f) dir = reflect_dir(incident, at.normal);
    ray.org = offset_ray_origin(at.position, at.normal);
  }
  ray.dir = glm::normalize(dir);
  return ray;
}

}  // namespace

PassOutcome run_refraction_pass(const FrameContext& ctx, const GBuffer& g, RaySink& sink,
                                RefractionResult& out) {
  const RefractionSpec& spec = ctx.passes.refraction;
  out.rays.clear();
  if (!spec.enabled) return {"disabled in the spec"};
  sink.set_pass(PassId::Refraction);
  uint32_t per_sample = spec.rays_per_pixel * spec.max_depth;
  for (uint32_t i : g.select(spec.resolution_scale, ctx.frame)) {
    const GSample& s = g.samples[i];
    if (!s.surface.hit() || ctx.scene.materials.materials[s.material].transmission <= 0.0f)
      continue;
    Pcg32 rng = make_rng(ctx.seed, RngStream::Refraction, ctx.frame, i);
    for (uint32_t j = 0; j < spec.rays_per_pixel; ++j) {
      Surface at = s.surface;
      glm::vec3 incident = s.view;
      for (uint32_t depth = 0; depth < spec.max_depth; ++depth) {
        glm::vec2 u(rng.uniform(), rng.uniform());
        Ray ray = next_ray(ctx, at, ctx.scene.material_of(at.prim), incident, u);
        ray.pixel = s.pixel;
        ray.sample = ray_sample_id(s.index, per_sample, j * spec.max_depth + depth);
        Surface next = ctx.scene.shoot_surface(sink, ray, at.prim);
        bool more = next.hit() && ctx.scene.material_of(next.prim).transmission > 0.0f;
        at = next;
        incident = ray.dir;
        if (!more) break;
      }
      out.rays.push_back({i, at});
    }
  }
  if (out.rays.empty()) return {"no transmissive surface in view"};
  return {};
}

}  // namespace rtsim::pipeline
