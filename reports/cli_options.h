// Command-line options shared by the commands of reports/ (run, sweep, regress,
// speed-vs-error): the workload overrides of `rtsim trace`, and the sampling options.
#pragma once

#include <CLI/CLI.hpp>

#include "model/fidelity/sample_plan.h"
#include "reports/trace_step.h"

namespace rtsim::reports {

inline void add_workload_options(CLI::App& cmd, TraceRequest& request) {
  cmd.add_option("--resolution", request.resolution, "Image size WxH (overrides the spec)");
  cmd.add_option("--frames", request.frames, "Frames to trace (overrides the spec)")
      ->check(CLI::PositiveNumber);
  cmd.add_option_function<uint64_t>(
      "--seed", [&request](const uint64_t& seed) { request.seed = seed; },
      "Random seed of the workload (overrides the spec)");
  cmd.add_option("--scene", request.scene, "Scene file or built-in (replaces the spec's scene)");
}

inline void add_sampling_options(CLI::App& cmd, SamplingConfig& sampling) {
  cmd.add_option("--window", sampling.window_rays,
                 "Sampled level: rays measured per window (0: 4 x ray slots, >= 1024)")
      ->capture_default_str();
  cmd.add_option("--warmup", sampling.warmup_rays,
                 "Sampled level: rays simulated before each window (-1: the ray slots)")
      ->capture_default_str();
  cmd.add_option("--sample-seed", sampling.seed, "Sampled level: seed of the window offsets")
      ->capture_default_str();
  cmd.add_flag("!--no-warm-pass", sampling.warm_pass,
               "Sampled level: measure without simulating the windows once first");
}

}  // namespace rtsim::reports
