// Progress of the long phases before a simulation, on stderr as the simulation's own
// (model/sc/sim_progress.h): a bar on a terminal, plain lines otherwise.
#pragma once

#include <cstdint>
#include <functional>

#include "model/bvh/bvh_image.h"
#include "workloads/pipeline/pipeline.h"

namespace rtsim::reports {

// For pipeline::TraceOptions::progress: the frame and pass being traced.
std::function<void(uint32_t frame, uint32_t frames, pipeline::PassId pass)> trace_progress();

// build_bvh_image, saying what it builds before and how long it took after (unless quiet).
BvhImage build_bvh_with_progress(const TriangleMesh& mesh, const BvhConfig& config, bool quiet);

}  // namespace rtsim::reports
