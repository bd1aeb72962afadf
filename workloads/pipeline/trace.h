// `rtsim trace` as a library call: load the workload's scene, build Embree over it, run the
// pipeline for every frame into a ray stream, and write the preview pictures.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "workloads/pipeline/pipeline.h"
#include "workloads/pipeline/spec.h"

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
};

// Command-line overrides of a spec; unset fields keep the spec's value. A new scene also makes
// the camera automatic (the spec's lights and material rules stay).
struct SpecOverrides {
  std::optional<uint32_t> frames, width, height;
  std::optional<uint64_t> seed;
  std::optional<std::string> scene;
};
void apply_overrides(WorkloadSpec& spec, const SpecOverrides& overrides);
// From command-line text: resolution "WxH" or "" (InputError if malformed), frames 0 = unset.
SpecOverrides make_overrides(const std::string& resolution, uint32_t frames,
                             std::optional<uint64_t> seed, const std::string& scene);

// A spec file (.toml), or a scene (built-in name or file) with the default spec.
WorkloadSpec load_workload(const std::string& workload);

TraceResult trace_workload(const WorkloadSpec& spec, const TraceOptions& options);

}  // namespace rtsim::pipeline
