// The first step of `rtsim run`, `sweep`, `regress` and `speed-vs-error`: trace a workload
// (spec file or built-in scene) into a folder, once. The folder holds
//   rays.rays      the ray stream
//   trace.json     what was asked (the request) and the pipeline's summary: scene, triangles,
//                  rays per pass against the budget, passes skipped and why
//   preview.png    the shaded last frame, and preview.density-PASS.png per pass
// A folder whose trace.json records the same request (and the same spec file contents) is
// reused as it is, so sweeps and reruns trace each workload once.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace rtsim::reports {

struct TraceRequest {
  std::string workload;    // spec file (.toml) or built-in scene name
  std::string resolution;  // "WxH" or "" (the spec's)
  uint32_t frames = 0;     // 0: the spec's
  std::optional<uint64_t> seed{};
  std::string scene{};                     // replaces the spec's scene; "" keeps it
  std::string camera{}, look_at{}, up{};   // "X,Y,Z", or "" for the spec's
  std::optional<uint32_t> camera_index{};  // the scene file's camera N
  std::optional<double> fov{};             // degrees
};

struct TraceOutcome {
  std::string dir, stream, preview;  // preview: "" if none was written
  nlohmann::ordered_json summary;    // trace.json
};

constexpr const char* kTraceSchema = "rtsim.trace/1";

// The request as trace.json records it: a spec file by absolute path and the hash of its
// contents. Sweeps name their points by it before anything is traced.
nlohmann::ordered_json trace_request_json(const TraceRequest& request);

// Whether dir holds a finished trace of this request (trace_into would reuse it).
bool trace_is_current(const TraceRequest& request, const std::string& dir);

// Traces into dir (created if needed), or reuses it. Throws InputError on a bad workload.
TraceOutcome trace_into(const TraceRequest& request, const std::string& dir, bool quiet);

// Reads a folder written by trace_into (InputError if it is not one).
TraceOutcome read_trace_dir(const std::string& dir);

// Whether path names a ray stream (a .rays file), which `rtsim run` takes in place of a trace.
bool is_stream_file(const std::string& path);

// A stream traced elsewhere (`rtsim trace`, `hardcases`) as a trace: a summary from its header
// (workload, scene, grid, frames, rays), without what only a trace folder records (passes,
// triangles, lights: empty or null). InputError naming the file if it is no valid stream.
TraceOutcome read_stream_trace(const std::string& stream);
nlohmann::ordered_json stream_summary(const std::string& stream);

// --from-trace PATH: a trace folder or a stream file.
TraceOutcome read_trace_source(const std::string& path);

}  // namespace rtsim::reports
