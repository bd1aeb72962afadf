// Diffuse GI pass (Pica Pica): surfels are spawned where the screen is least covered
// (surfels.h), then every surfel shoots cosine-weighted closest-hit rays over its hemisphere,
// the count set by the per-frame budget (250k rays in the talk) with more rays for new
// surfels. Explicit light connections: from each GI hit, one shadow ray to a light chosen at
// random (gi_light, RayType::Shadow). GI rays are tagged with the pixel their surfel was
// spawned from. Each surfel accumulates the irradiance its rays found (for the preview).
#pragma once

#include "workloads/pipeline/context.h"
#include "workloads/pipeline/gbuffer.h"
#include "workloads/pipeline/ray_sink.h"
#include "workloads/pipeline/surfels.h"

namespace rtsim::pipeline {

struct GiOutcome {
  PassOutcome gi, light;
  uint32_t spawned = 0;
};

// Why diffuse GI has nothing to do in this scene, or "" if it has.
std::string gi_skip_reason(const SceneContext& scene, const GiSpec& spec);

GiOutcome run_gi_pass(const FrameContext& ctx, const GBuffer& g, SurfelCache& cache, RaySink& sink);

}  // namespace rtsim::pipeline
