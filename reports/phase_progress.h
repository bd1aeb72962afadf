// Progress of the long phases before a simulation, on stderr as the simulation's own
// (model/sc/sim_progress.h): a bar on a terminal, plain lines otherwise.
#pragma once

#include <cstdint>
#include <functional>

#include "model/bvh/two_level.h"
#include "workloads/scene.h"
#include "workloads/pipeline/pipeline.h"

namespace rtsim::reports {

// For pipeline::TraceOptions::progress: the frame and pass being traced.
std::function<void(uint32_t frame, uint32_t frames, pipeline::PassId pass)> trace_progress();

// The scene's BVH under config.instancing (model/bvh/two_level.h: one level, or two, then
// over scene.instanced, which a flat scene gets as one instance), saying what it builds
// before and how long it took after (unless quiet). A TwoLevelBvh without bottom levels is
// one level.
TwoLevelBvh build_scene_bvh(Scene& scene, const BvhConfig& config, bool quiet);

// "N nodes (M in the TLAS), X MiB (Y B a unique triangle)": what a built BVH holds.
std::string bvh_summary(const TwoLevelBvh& bvh);

}  // namespace rtsim::reports
