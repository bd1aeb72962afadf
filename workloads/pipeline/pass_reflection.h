// Reflection pass (Pica Pica's raytraced reflections): from glossy surfaces (roughness at most
// max_roughness, in the base or a clear coat), on a grid of resolution_scale (half resolution:
// 1/4 ray per pixel). Directions importance-sample the GGX NDF (Walter et al. 2007) with a
// Halton sequence, Cranley-Patterson rotated per pixel (PBRT), one point per frame; a direction
// below the horizon is re-rolled with another Halton point (at most max_rerolls times, then the
// mirror direction).
// Layered materials shoot one ray for the stack (layers.h).
#pragma once

#include <cstdint>
#include <vector>

#include "workloads/pipeline/context.h"
#include "workloads/pipeline/gbuffer.h"
#include "workloads/pipeline/layers.h"
#include "workloads/pipeline/ray_sink.h"

namespace rtsim::pipeline {

struct ReflectionRecord {
  uint32_t sample = 0;  // G-buffer sample it left from
  glm::vec3 dir{0.0f};
  Surface hit;          // what it hit (hit() false: it escaped)
  float pdf = 0.0f;     // density of dir over the whole layer stack
  uint8_t layer = 0;    // layer chosen, 0 = top
  uint8_t rerolls = 0;  // directions rejected below the horizon
};

struct ReflectionResult {
  std::vector<ReflectionRecord> rays;
};

// The reflection direction for view v (unit, toward the viewer) at normal n, from Halton
// index `index` rotated by `rotation`; rerolls counts rejected directions.
glm::vec3 sample_reflection(const LayerStack& stack, int layer, const glm::vec3& v,
                            const glm::vec3& n, uint32_t index, glm::vec2 rotation,
                            uint32_t max_rerolls, uint32_t& rerolls);

PassOutcome run_reflection_pass(const FrameContext& ctx, const GBuffer& g, RaySink& sink,
                                ReflectionResult& out);

}  // namespace rtsim::pipeline
