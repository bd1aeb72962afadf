#include "workloads/pipeline/pass_gi.h"

#include <glm/geometric.hpp>

#include "workloads/pipeline/offset.h"
#include "workloads/pipeline/rng.h"
#include "workloads/pipeline/sampling.h"
#include "workloads/pipeline/shading.h"

namespace rtsim::pipeline {
namespace {

struct GiHit {
  uint32_t surfel = 0;
  Surface surface;
  float visibility = -1.0f;  // of the chosen light
  uint32_t light = 0;
};

void shoot_gi_rays(const FrameContext& ctx, SurfelCache& cache, RaySink& sink,
                   std::vector<GiHit>& hits) {
  sink.set_pass(PassId::DiffuseGI);
  auto& surfels = cache.surfels();
  std::vector<uint32_t> counts = gi_ray_counts(surfels, ctx.passes.gi, ctx.frame);
  for (uint32_t s = 0; s < surfels.size(); ++s) {
    Surfel& surfel = surfels[s];
    Basis basis(surfel.normal);
    Pcg32 rng = make_rng(ctx.seed, RngStream::DiffuseGI, ctx.frame, s);
    for (uint32_t k = 0; k < counts[s]; ++k) {
      Ray ray = ctx.ray(RayType::DiffuseGI, Query::ClosestHit);
      ray.org = offset_ray_origin(surfel.position, surfel.normal);
      ray.dir = glm::normalize(
          basis.to_world(sample_cosine_hemisphere(glm::vec2(rng.uniform(), rng.uniform()))));
      ray.pixel = surfel.pixel;
      ray.sample = uint16_t(k);
      Surface hit = ctx.scene.shoot_surface(sink, ray, surfel.prim);
      if (hit.hit()) {
        hits.push_back({s, hit, -1.0f, 0});
      } else {
        // With cosine sampling, irradiance is pi times the mean incoming radiance.
        surfel.irradiance_sum += kPi * ctx.scene.sky;
        surfel.irradiance_samples++;
      }
    }
  }
}

// Returns whether any ray was shot.
bool connect_lights(const FrameContext& ctx, const SurfelCache& cache, RaySink& sink,
                    std::vector<GiHit>& hits) {
  const auto& lights = ctx.scene.lights;
  sink.set_pass(PassId::GiLight);
  uint64_t before = sink.count(PassId::GiLight);
  for (size_t h = 0; h < hits.size(); ++h) {
    GiHit& hit = hits[h];
    Pcg32 rng = make_rng(ctx.seed, RngStream::GiLight, ctx.frame, h);
    hit.light = rng.below(uint32_t(lights.size()));
    glm::vec2 u(rng.uniform(), rng.uniform());
    Ray ray = ctx.ray(RayType::Shadow, Query::AnyHit);
    if (!make_shadow_ray(lights[hit.light], hit.surface.position, hit.surface.normal, u, ray))
      continue;
    const Surfel& surfel = cache.surfels()[hit.surfel];
    ray.pixel = surfel.pixel;
    ray.sample = uint16_t(h);
    hit.visibility = ctx.scene.shoot_occluded(sink, ray, hit.surface.prim) ? 0.0f : 1.0f;
  }
  return sink.count(PassId::GiLight) > before;
}

}  // namespace

std::string gi_skip_reason(const SceneContext& scene, const GiSpec& spec) {
  if (!spec.enabled) return "disabled in the spec";
  if (spec.budget == 0) return "budget is 0";
  bool emissive = false;
  for (const ShadingMaterial& m : scene.materials.materials) emissive |= m.emissive();
  if (scene.lights.empty() && !emissive && scene.sky == glm::vec3(0.0f))
    return "nothing to bounce: no lights, emission or sky";
  return "";
}

GiOutcome run_gi_pass(const FrameContext& ctx, const GBuffer& g, SurfelCache& cache,
                      RaySink& sink) {
  GiOutcome out;
  std::string reason = gi_skip_reason(ctx.scene, ctx.passes.gi);
  if (!reason.empty()) {
    out.gi.skipped = out.light.skipped = reason;
    return out;
  }
  out.spawned = spawn_surfels(ctx, g, cache);
  if (cache.surfels().empty()) {
    out.gi.skipped = out.light.skipped = "no surfels (no surface in view)";
    return out;
  }
  std::vector<GiHit> hits;
  shoot_gi_rays(ctx, cache, sink, hits);
  const auto& lights = ctx.scene.lights;
  if (!ctx.passes.gi.light_connections)
    out.light.skipped = "disabled in the spec";
  else if (lights.empty())
    out.light.skipped = "no lights";
  else if (hits.empty())
    out.light.skipped = "every GI ray escaped";
  else if (!connect_lights(ctx, cache, sink, hits))
    out.light.skipped = "no GI hit faces a light";
  // One light stands for all: its contribution is scaled by the number of lights.
  std::vector<float> visibility(lights.size(), -1.0f);
  for (const GiHit& hit : hits) {
    std::fill(visibility.begin(), visibility.end(), -1.0f);
    if (!lights.empty()) visibility[hit.light] = hit.visibility * float(lights.size());
    Surfel& surfel = cache.surfels()[hit.surfel];
    glm::vec3 radiance = shade_surface(ctx.scene, hit.surface, visibility.data());
    // The light connection already brings an emitter that became a light; do not count it twice.
    if (ctx.scene.emission_is_light) radiance -= ctx.scene.material_of(hit.surface.prim).emission;
    surfel.irradiance_sum += kPi * radiance;
    surfel.irradiance_samples++;
  }
  return out;
}

}  // namespace rtsim::pipeline
