// Shadow pass: from every camera sample that hit a surface, rays_per_pixel any-hit rays per
// light, ending at the light. Point and spot lights give hard shadows (one ray to the light's
// position); spherical lights and directional lights with an angular diameter sample a uniform
// cone toward the light (PBRT), whose width sets the penumbra. No ray where the light is behind
// the surface or outside a spot cone.
#pragma once

#include <vector>

#include "workloads/pipeline/context.h"
#include "workloads/pipeline/gbuffer.h"
#include "workloads/pipeline/ray_sink.h"

namespace rtsim::pipeline {

struct ShadowResult {
  uint32_t lights = 0;
  // Per (G-buffer sample, light), sample-major: fraction of rays that reached the light, or -1
  // where no ray was shot.
  std::vector<float> visibility;
};

PassOutcome run_shadow_pass(const FrameContext& ctx, const GBuffer& g, RaySink& sink,
                            ShadowResult& out);

}  // namespace rtsim::pipeline
