#include "workloads/pipeline/trace.h"

#include <chrono>
#include <filesystem>
#include <memory>

#include "traces/embree_scene.h"
#include "traces/error.h"
#include "traces/stream.h"
#include "workloads/pipeline/preview.h"
#include "workloads/scene.h"

namespace rtsim::pipeline {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

void apply_overrides(WorkloadSpec& spec, const SpecOverrides& o) {
  if (o.frames) spec.frames = *o.frames;
  if (o.width) spec.width = *o.width;
  if (o.height) spec.height = *o.height;
  if (o.seed) spec.seed = *o.seed;
  if (o.scene) {
    // The spec's camera was placed for its own scene: fit one to the new scene instead.
    spec.scene = *o.scene;
    spec.camera.position.reset();
    spec.camera.look_at.reset();
    spec.camera.keys.clear();
  }
}

SpecOverrides make_overrides(const std::string& resolution, uint32_t frames,
                             std::optional<uint64_t> seed, const std::string& scene) {
  SpecOverrides o;
  if (!resolution.empty()) {
    uint32_t w = 0, h = 0;
    if (!parse_resolution(resolution, w, h))
      throw InputError("--resolution " + resolution + ": expected WxH, e.g. 1920x1080");
    o.width = w;
    o.height = h;
  }
  if (frames > 0) o.frames = frames;
  o.seed = seed;
  if (!scene.empty()) o.scene = scene;
  return o;
}

WorkloadSpec load_workload(const std::string& workload) {
  bool toml = workload.size() > 5 && workload.compare(workload.size() - 5, 5, ".toml") == 0;
  if (toml) return read_spec(workload);
  // A scene (built-in or file) with the default spec.
  if (is_builtin_scene(workload) || std::filesystem::exists(workload))
    return default_spec_for_scene(workload);
  throw_input_error(workload, "", "no such workload spec (.toml), scene file or built-in scene");
}

TraceResult trace_workload(const WorkloadSpec& spec, const TraceOptions& options) {
  auto start = std::chrono::steady_clock::now();
  Scene scene = load_scene(spec.scene);
  double load_seconds = seconds_since(start);
  start = std::chrono::steady_clock::now();
  EmbreeScene embree(scene.mesh, options.embree_threads);
  double build_seconds = seconds_since(start);
  start = std::chrono::steady_clock::now();

  Pipeline pipeline(spec, scene, embree);
  std::unique_ptr<RayStreamWriter> writer;
  if (!options.output.empty()) {
    StreamHeader header;
    header.scene_source = scene.source;
    header.scene_fingerprint = scene.fingerprint;
    header.workload = spec.name;
    header.generator = options.generator;
    header.seed = spec.seed;
    header.frame_count = spec.frames;
    header.width = spec.width;
    header.height = spec.height;
    writer = std::make_unique<RayStreamWriter>(options.output, header);
  }
  RaySink sink(writer.get(), spec.width, spec.height, !options.preview.empty());
  if (options.progress)
    pipeline.on_pass = [&](uint32_t frame, PassId pass) {
      options.progress(frame, spec.frames, pass);
    };
  FrameResults frame;
  for (uint32_t f = 0; f < spec.frames; ++f) pipeline.run_frame(f, sink, frame);
  if (writer) writer->finish();

  TraceResult result;
  if (!options.preview.empty()) {
    write_preview(options.preview, pipeline, frame);
    result.images.push_back(options.preview);
    for (auto& path : write_density_images(options.preview, sink, spec.width, spec.height))
      result.images.push_back(path);
  }
  result.summary = pipeline.summary();
  result.summary.load_seconds = load_seconds;
  result.summary.build_seconds = build_seconds;
  result.summary.trace_seconds = seconds_since(start);
  return result;
}

}  // namespace rtsim::pipeline
