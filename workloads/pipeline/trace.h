// `rtsim trace` as a library call: load the workload's scene, build Embree over it, run the
// pipeline for every frame into a ray stream, and write the preview pictures.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "workloads/pipeline/pipeline.h"
#include "workloads/pipeline/spec.h"
#include "workloads/pipeline/workload.h"

namespace rtsim::pipeline {

struct TraceOptions {
  std::string output;   // .rays path; empty: count rays only
  std::string preview;  // PNG path of the shaded last frame (+ density images); empty: none
  std::string generator = "rtsim";
  int embree_threads = 1;  // 1 keeps the run single-threaded (and its timing "one core")
  // Called before each pass of each frame.
  std::function<void(uint32_t frame, uint32_t frames, PassId pass)> progress;
};

struct TraceResult {
  RunSummary summary;
  std::vector<std::string> images;  // pictures written
  std::vector<std::string> notes;   // what the scene decided for the spec (adopt_scene_defaults)
};

TraceResult trace_workload(const WorkloadSpec& spec, const TraceOptions& options);

}  // namespace rtsim::pipeline
