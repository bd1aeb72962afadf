// Ambient-occlusion pass: from camera hits on a grid of resolution_scale, rays_per_pixel short
// any-hit rays, cosine-weighted over the hemisphere, of length radius.
#pragma once

#include <vector>

#include "workloads/pipeline/context.h"
#include "workloads/pipeline/gbuffer.h"
#include "workloads/pipeline/ray_sink.h"

namespace rtsim::pipeline {

struct AoResult {
  std::vector<uint32_t> samples;  // G-buffer samples that shot AO rays
  std::vector<float> visibility;  // fraction of their rays unoccluded
};

// The AO ray length: ao.radius, or 2% of the scene diagonal.
float ao_radius(const FrameContext& ctx);

PassOutcome run_ao_pass(const FrameContext& ctx, const GBuffer& g, RaySink& sink, AoResult& out);

}  // namespace rtsim::pipeline
