// Command-line options shared by the commands of reports/ (run, sweep, regress,
// speed-vs-error): the workload overrides of `rtsim trace`, and the sampling options.
#pragma once

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "model/fidelity/sample_plan.h"
#include "reports/trace_step.h"
#include "traces/error.h"
#include "traces/memory_plan.h"
#include "traces/stream.h"

namespace rtsim::reports {

// Frames as a workload spec takes them.
inline CLI::Range frame_range() {
  return CLI::Range(uint32_t(1), kMaxFrames);
}

// An unsigned option given a negative number (CLI11 would wrap "-1" round to 2^64-1).
inline CLI::Validator non_negative() {
  return CLI::Validator(
      [](std::string& text) {
        return text.find('-') == std::string::npos ? std::string()
                                                   : "'" + text + "' must not be negative";
      },
      "UINT");
}

// Rays a command generates and holds in memory (bench's and bench-sim's --rays): 1 to
// 2^32 - 1, as a ray's pixel index counts them, and planned before they are made.
constexpr uint64_t kMaxGeneratedRays = 0xffffffffull;
constexpr uint64_t kGeneratedRayBytes = 64;  // a Ray in a vector, and the sampler's share

inline CLI::Option* add_generated_rays_option(CLI::App& cmd, size_t& rays,
                                              const std::string& description) {
  return cmd.add_option("--rays", rays, description)
      ->check(CLI::Range(uint64_t(1), kMaxGeneratedRays))
      ->capture_default_str();
}

// InputError naming `option` if `rays` generated rays do not fit the memory available.
inline void require_generated_ray_memory(uint64_t rays, const std::string& option) {
  require_memory(rays * kGeneratedRayBytes, option, std::to_string(rays) + " generated rays",
                 "ask for fewer rays");
}

inline void add_camera_options(CLI::App& cmd, std::string& camera, std::string& look_at,
                               std::string& up, std::optional<uint32_t>& camera_index,
                               std::optional<double>& fov) {
  cmd.add_option("--camera", camera, "Camera position X,Y,Z (overrides the spec)");
  cmd.add_option("--look-at", look_at, "Point the camera looks at X,Y,Z (overrides the spec)");
  cmd.add_option("--up", up, "Up direction of the image X,Y,Z (overrides the spec)");
  cmd.add_option_function<uint32_t>(
         "--camera-index", [&camera_index](const uint32_t& n) { camera_index = n; },
         "The scene file's camera N (0 the first; rtsim scene-info lists them), whole")
      ->check(non_negative());
  cmd.add_option_function<double>(
      "--fov", [&fov](const double& degrees) { fov = degrees; },
      "Vertical field of view, degrees (overrides the spec's and a file camera's)");
}

inline void add_workload_options(CLI::App& cmd, TraceRequest& request) {
  cmd.add_option("--resolution", request.resolution, "Image size WxH (overrides the spec)");
  cmd.add_option("--frames", request.frames, "Frames to trace (overrides the spec)")
      ->check(frame_range());
  cmd.add_option_function<uint64_t>(
         "--seed", [&request](const uint64_t& seed) { request.seed = seed; },
         "Random seed of the workload (overrides the spec)")
      ->check(non_negative());
  cmd.add_option("--scene", request.scene, "Scene file or built-in (replaces the spec's scene)");
  add_camera_options(cmd, request.camera, request.look_at, request.up, request.camera_index,
                     request.fov);
}

// --set and --flatten, which is --set bvh.instancing="flatten": one BVH level over the
// world-space triangles, also where the scene places a mesh more than once.
inline void add_config_overrides(CLI::App& cmd, std::vector<std::string>& sets) {
  cmd.add_option("--set", sets, "Override a config key: --set rt.l1.size_bytes=65536")
      ->allow_extra_args(false);
  // Taken after --set has stored its values (CLI11 runs option callbacks in the order added).
  cmd.add_flag_callback(
      "--flatten", [&sets] { sets.push_back("bvh.instancing=\"flatten\""); },
      "One BVH over the world-space triangles, not two levels over the scene's instances");
}

// With --from-trace DIR the stream is reused as it was traced: a workload or an option that
// would trace it differently is refused (InputError), not silently ignored.
// workload_is_trace: the positional workload is the trace (a .rays stream), not a change to it.
inline void refuse_workload_with_trace(const CLI::App& cmd, const std::string& from_trace,
                                       bool workload_is_trace = false) {
  if (from_trace.empty()) return;
  for (std::string option : {"workload", "--resolution", "--frames", "--seed", "--scene",
                             "--camera", "--look-at", "--up", "--camera-index", "--fov"})
    if (cmd.count(option) > 0 && !(workload_is_trace && option == "workload"))
      throw InputError(std::string(cmd.get_name()) + ": --from-trace " + from_trace +
                       " reuses that trace as it was traced; " +
                       (option[0] == '-' ? std::string(option) : "a workload") +
                       " cannot change it (trace anew without --from-trace)");
}

// --sample-method takes one method, or with `several` a comma-separated list of them.
inline void add_sampling_options(CLI::App& cmd, SamplingConfig& sampling,
                                 std::vector<std::string>& methods, bool several = false) {
  cmd.add_option("--sample-method", methods,
                 several ? "Sampled level: scale-model, warmed, windows (comma-separated)"
                         : "Sampled level: scale-model (one run on a scaled machine), warmed "
                           "(the same, the other units' reads warming its L2) or windows")
      ->delimiter(several ? ',' : '\0')
      ->expected(1, several ? 3 : 1)
      ->capture_default_str();
  cmd.add_option("--window", sampling.window_rays,
                 "Windows method: rays measured per window (0: 4 x ray slots, >= 1024)")
      ->capture_default_str();
  cmd.add_option("--warmup", sampling.warmup_rays,
                 "Windows method: rays simulated before each window (-1: the ray slots)")
      ->capture_default_str();
  cmd.add_option("--sample-seed", sampling.seed,
                 "Sampled level: seed of the warp draw or of the window offsets")
      ->capture_default_str();
  cmd.add_flag("!--no-warm-pass", sampling.warm_pass,
               "Windows method: measure without simulating the windows once first");
}

// The methods named by --sample-method; InputError for an unknown one, or for the window
// options without the windows method (the scale model has no windows, warm-up or warm pass).
inline std::vector<SampleMethod> sampling_methods(const CLI::App& cmd,
                                                  const std::vector<std::string>& names) {
  std::vector<SampleMethod> methods;
  for (const std::string& name : names) {
    auto method = sample_method_from_name(name);
    if (!method)
      throw InputError("--sample-method: unknown method '" + name +
                       "' (scale-model, warmed, windows)");
    methods.push_back(*method);
  }
  bool windows = std::count(methods.begin(), methods.end(), SampleMethod::Windows) > 0;
  for (const char* option : {"--window", "--warmup", "--no-warm-pass"})
    if (!windows && cmd.count(option) > 0)
      throw InputError(std::string(option) + " applies to --sample-method windows only");
  return methods;
}

}  // namespace rtsim::reports
