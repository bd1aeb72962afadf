// Reflected-shadow pass: from every reflection hit, one any-hit ray per light (as the shadow
// pass does for camera hits), so the reflected surface can be lit with shadows. At half
// resolution that is Pica Pica's 1/4 reflected-shadow ray per pixel.
#pragma once

#include <vector>

#include "workloads/pipeline/context.h"
#include "workloads/pipeline/gbuffer.h"
#include "workloads/pipeline/pass_reflection.h"
#include "workloads/pipeline/ray_sink.h"

namespace rtsim::pipeline {

struct ReflectedShadowResult {
  uint32_t lights = 0;
  // Per (reflection ray, light): 1 lit, 0 shadowed, -1 no ray.
  std::vector<float> visibility;
};

PassOutcome run_reflected_shadow_pass(const FrameContext& ctx, const GBuffer& g,
                                      const ReflectionResult& reflections, RaySink& sink,
                                      ReflectedShadowResult& out);

}  // namespace rtsim::pipeline
