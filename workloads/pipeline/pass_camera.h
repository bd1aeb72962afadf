// Camera pass: one primary ray per camera sample, closest hit by Embree, filling the G-buffer
// (position, normal, material, depth). In a hybrid renderer this is the raster G-buffer pass;
// here it is traced so the hardware model sees the primary rays too.
#pragma once

#include <vector>

#include "workloads/pipeline/context.h"
#include "workloads/pipeline/gbuffer.h"
#include "workloads/pipeline/ray_sink.h"
#include "workloads/pipeline/samples.h"

namespace rtsim::pipeline {

// Emits the rays into sink (may be null: a probe that writes nothing).
GBuffer run_camera_pass(const FrameContext& ctx, const std::vector<SamplePosition>& positions,
                        RaySink* sink);

}  // namespace rtsim::pipeline
