#include "workloads/pipeline/pipeline.h"

#include <algorithm>
#include <glm/geometric.hpp>

#include "traces/error.h"
#include "workloads/pipeline/pass_camera.h"
#include "workloads/pipeline/pass_gi.h"
#include "workloads/scene.h"

namespace rtsim::pipeline {
namespace {

SceneContext make_scene_context(const WorkloadSpec& spec, const Scene& scene,
                                const MaterialTable& materials, const EmbreeScene& embree) {
  SceneContext ctx{scene,    materials,
                   embree,   resolve_lights(spec, scene, materials),
                   spec.sky, glm::length(scene.bounds.extent())};
  if (!(ctx.diagonal > 0.0f)) ctx.diagonal = 1.0f;
  ctx.emission_is_light = spec.lights_from_emission;
  return ctx;
}

// Importance of each full-resolution pixel from a probe at a quarter of the resolution.
std::vector<float> upsample(const std::vector<float>& small, uint32_t sw, uint32_t sh,
                            uint32_t width, uint32_t height) {
  std::vector<float> out(size_t(width) * height);
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x)
      out[size_t(y) * width + x] =
          small[size_t(std::min(sh - 1, y * sh / height)) * sw + std::min(sw - 1, x * sw / width)];
  return out;
}

uint64_t sum_over_passes(const std::array<PassSummary, kPassCount>& passes,
                         uint64_t PassSummary::*count) {
  uint64_t sum = 0;
  for (const PassSummary& p : passes) sum += p.*count;
  return sum;
}

}  // namespace

uint64_t RunSummary::total_rays() const {
  return sum_over_passes(passes, &PassSummary::rays);
}

uint64_t RunSummary::total_alpha_rays() const {
  return sum_over_passes(passes, &PassSummary::alpha_rays);
}

uint64_t pass_budget(const WorkloadSpec& spec, PassId pass, size_t lights) {
  const PassSpecs& p = spec.passes;
  uint64_t samples = spec.samples.count ? spec.samples.count : uint64_t(spec.width) * spec.height;
  auto cells = [&](const PassRate& rate) {
    if (!rate.enabled) return uint64_t(0);
    uint64_t c = rate.resolution_scale >= 1.0f
                     ? samples
                     : GBuffer::cell_count(spec.width, spec.height, rate.resolution_scale);
    return c * rate.rays_per_pixel;
  };
  switch (pass) {
    case PassId::Camera: return samples;
    case PassId::Shadow: return cells(p.shadow) * lights;
    case PassId::Reflection: return cells(p.reflection);
    case PassId::ReflectedShadow: return p.reflected_shadow ? cells(p.reflection) * lights : 0;
    case PassId::DiffuseGI: return p.gi.enabled ? p.gi.budget : 0;
    case PassId::GiLight: return p.gi.enabled && p.gi.light_connections && lights ? p.gi.budget : 0;
    case PassId::AO: return cells(p.ao);
    case PassId::Refraction: return cells(p.refraction) * p.refraction.max_depth;
    case PassId::Translucency: return cells(p.translucency);
  }
  return 0;
}

Pipeline::Pipeline(const WorkloadSpec& spec, const Scene& scene, const EmbreeScene& embree)
    : spec_(spec),
      materials_(assign_materials(scene, spec.materials)),
      scene_(make_scene_context(spec_, scene, materials_, embree)),
      surfels_(spec.passes.gi.surfel_radius.value_or(0.0f)) {
  if (!spec.camera.position || !spec.camera.look_at)
    auto_fit_ = auto_view(materials_.triangles, scene.bounds, embree, spec.camera.up,
                          spec.camera.fov, float(spec.width) / float(spec.height));
  // A narrow field of view and an extreme aspect can push the fitted camera far out.
  glm::vec3 position = spec.camera.position.value_or(auto_fit_.position);
  if (std::string problem = camera_origin_problem(position); !problem.empty())
    throw_input_error(spec.file.empty() ? spec.name : spec.file, "camera",
                      "the camera fit to the scene stands at " + format_point(position) + ": " +
                          problem + "; set camera.position and camera.look_at");
  summary_.workload = spec.name;
  summary_.scene_source = scene.source;
  summary_.triangles = scene.triangle_count();
  summary_.width = spec.width;
  summary_.height = spec.height;
  summary_.frames = spec.frames;
  summary_.lights = scene_.lights.size();
  summary_.camera_position = spec.camera.position.value_or(auto_fit_.position);
  summary_.camera_look_at = spec.camera.look_at.value_or(auto_fit_.look_at);
  WorkloadSpec hd = spec;  // the ray mix the budgets were set for (workloads/README.md)
  hd.width = kMixWidth;
  hd.height = kMixHeight;
  for (int p = 0; p < kPassCount; ++p) {
    summary_.passes[size_t(p)].budget = pass_budget(spec, PassId(p), scene_.lights.size());
    summary_.passes[size_t(p)].budget_per_pixel_1080p =
        double(pass_budget(hd, PassId(p), scene_.lights.size())) / (double(kMixWidth) * kMixHeight);
  }
}

void Pipeline::enter(uint32_t frame, PassId pass) {
  if (on_pass) on_pass(frame, pass);
}

void Pipeline::record(PassId pass, const PassOutcome& outcome) {
  PassSummary& s = summary_.passes[size_t(pass)];
  if (outcome.skipped.empty() || warming_up_) return;
  if (s.frames_skipped++ == 0) s.reason = outcome.skipped;
}

std::vector<SamplePosition> Pipeline::place_samples(const FrameContext& ctx, RaySink& sink) {
  const SampleSpec& spec = spec_.samples;
  glm::vec2 jitter = frame_jitter(ctx.frame, spec_.camera.jitter);
  uint64_t count = spec.count ? spec.count : uint64_t(ctx.width) * ctx.height;
  if (spec.placement == Placement::Regular) return regular_samples(ctx.width, ctx.height, jitter);
  std::vector<float> importance;
  if (ctx.frame == 0) {
    // No previous frame yet: edges from a quarter-resolution probe that writes no rays.
    uint32_t sw = std::max(1u, ctx.width / 4), sh = std::max(1u, ctx.height / 4);
    FrameContext probe = ctx;
    probe.camera.width = probe.width = sw;
    probe.camera.height = probe.height = sh;
    GBuffer g = run_camera_pass(probe, regular_samples(sw, sh, glm::vec2(0.0f)), nullptr);
    SampleSpec edges_only = spec;
    edges_only.cost = false;
    importance = upsample(importance_map(g, {}, edges_only), sw, sh, ctx.width, ctx.height);
  } else {
    importance = importance_map(previous_, previous_cost_, spec);
  }
  std::fill(sink.frame_cost().begin(), sink.frame_cost().end(), 0u);
  return importance_samples(ctx.width, ctx.height, count, importance, spec.uniform_share,
                            spec_.seed, ctx.frame);
}

void Pipeline::run_frame(uint32_t frame, RaySink& sink, FrameResults& r) {
  warming_up_ = frame < spec_.warmup_frames;
  sink.set_warmup_frames(spec_.warmup_frames);
  uint32_t camera_frame = warming_up_ ? 0 : frame - spec_.warmup_frames;
  r.camera = camera_for_frame(spec_.camera, auto_fit_, camera_frame, spec_.frames, spec_.width,
                              spec_.height);
  FrameContext ctx{scene_, spec_.passes, r.camera, frame, spec_.seed, spec_.width, spec_.height};
  std::fill(sink.frame_cost().begin(), sink.frame_cost().end(), 0u);
  enter(frame, PassId::Camera);
  r.gbuffer = run_camera_pass(ctx, place_samples(ctx, sink), &sink);
  record(PassId::Camera,
         r.gbuffer.samples.empty() ? PassOutcome{"no camera samples"} : PassOutcome{});
  enter(frame, PassId::Shadow);
  record(PassId::Shadow, run_shadow_pass(ctx, r.gbuffer, sink, r.shadow));
  enter(frame, PassId::Reflection);
  record(PassId::Reflection, run_reflection_pass(ctx, r.gbuffer, sink, r.reflection));
  enter(frame, PassId::ReflectedShadow);
  record(PassId::ReflectedShadow,
         run_reflected_shadow_pass(ctx, r.gbuffer, r.reflection, sink, r.reflected_shadow));
  enter(frame, PassId::DiffuseGI);
  GiOutcome gi = run_gi_pass(ctx, r.gbuffer, surfels_, sink);
  record(PassId::DiffuseGI, gi.gi);
  record(PassId::GiLight, gi.light);
  enter(frame, PassId::AO);
  record(PassId::AO, run_ao_pass(ctx, r.gbuffer, sink, r.ao));
  enter(frame, PassId::Refraction);
  record(PassId::Refraction, run_refraction_pass(ctx, r.gbuffer, sink, r.refraction));
  enter(frame, PassId::Translucency);
  record(PassId::Translucency, run_translucency_pass(ctx, r.gbuffer, sink, r.translucency));
  for (int p = 0; p < kPassCount; ++p) {
    summary_.passes[size_t(p)].rays = sink.count(PassId(p));
    summary_.passes[size_t(p)].alpha_rays = sink.alpha_count(PassId(p));
  }
  summary_.surfels = surfels_.surfels().size();
  if (spec_.samples.placement == Placement::Importance) {
    previous_ = r.gbuffer;
    previous_cost_ = sink.frame_cost();
  }
}

}  // namespace rtsim::pipeline
