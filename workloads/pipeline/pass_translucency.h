// Translucency pass (Pica Pica, after Barré-Brisebois & Bouchard 2011): from camera hits on
// translucent materials (translucency > 0), on a grid of resolution_scale, flip the normal and
// push the origin inside (offset.h), then shoot rays_per_pixel closest-hit rays with uniform
// sphere directions. The half of the sphere that points back out through the entry point is
// mirrored into the inner half (it would only re-hit the surface it starts on), so directions
// are uniform over the inner hemisphere.
#pragma once

#include <vector>

#include "workloads/pipeline/context.h"
#include "workloads/pipeline/gbuffer.h"
#include "workloads/pipeline/ray_sink.h"

namespace rtsim::pipeline {

struct TranslucencyResult {
  std::vector<uint32_t> samples;
  std::vector<glm::vec3> radiance;  // mean unshadowed light found at the rays' hits
};

PassOutcome run_translucency_pass(const FrameContext& ctx, const GBuffer& g, RaySink& sink,
                                  TranslucencyResult& out);

}  // namespace rtsim::pipeline
