// Refraction pass (Pica Pica's transparency): from camera hits on transmissive materials
// (transmission > 0), a ray refracted by Snell's law with the material's IOR through a GGX
// microfacet normal sampled with the material's roughness (rough refraction; Walter et al.
// 2007). Where it hits glass again it crosses the next interface, up to max_depth rays per
// sample (2: into and out of a solid). Total internal reflection reflects instead. The origin
// is pushed to the far side of the surface (offset.h). No transmissive surface: no rays.
#pragma once

#include <vector>

#include "workloads/pipeline/context.h"
#include "workloads/pipeline/gbuffer.h"
#include "workloads/pipeline/ray_sink.h"

namespace rtsim::pipeline {

struct RefractionRecord {
  uint32_t sample = 0;
  Surface last_hit;  // where the last ray of the chain landed (hit() false: escaped)
};

struct RefractionResult {
  std::vector<RefractionRecord> rays;
};

PassOutcome run_refraction_pass(const FrameContext& ctx, const GBuffer& g, RaySink& sink,
                                RefractionResult& out);

}  // namespace rtsim::pipeline
