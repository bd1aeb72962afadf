#include "workloads/pipeline/trace.h"

#include <memory>

#include <fmt/core.h>

#include "traces/embree_scene.h"
#include "traces/host_clock.h"
#include "traces/memory_plan.h"
#include "traces/output_file.h"
#include "traces/stream.h"
#include "workloads/pipeline/instance_rules.h"
#include "workloads/pipeline/preview.h"
#include "workloads/pipeline/summary.h"
#include "workloads/pipeline/scene_defaults.h"
#include "workloads/scene.h"

namespace rtsim::pipeline {
namespace {

// What the workload set on the instances, and what Embree's per-frame top levels cost.
std::string settings_note(const Scene& scene, const EmbreeScene& embree) {
  const InstanceSettings& s = scene.instance_settings;
  std::string note = fmt::format("instances: {} of {} masked, {} moving", s.masks.size(),
                                 scene.instanced.instances.size(), s.moving.size());
  const std::vector<double>& seconds = embree.top_build_seconds();
  if (seconds.size() < 2) return note;
  double sum = 0.0;
  for (double t : seconds) sum += t;
  return note + fmt::format("; Embree built a top level for each of {} frames, {:.2f} ms a frame",
                            seconds.size(), 1e3 * sum / double(seconds.size()));
}

// Where the camera fitted to the scene stands, and why (workloads/README.md, "Your own scene").
std::string fitted_camera_note(const WorkloadSpec& spec, const Pipeline& pipeline) {
  const View& fit = pipeline.auto_fit();
  const char* what = !spec.camera.position && !spec.camera.look_at ? "camera fitted to the scene"
                     : !spec.camera.position ? "camera position fitted to the scene"
                                             : "camera look-at point fitted to the scene";
  return fmt::format(
      "{}: at {} looking at {}: {} (camera.position and camera.look_at, or --camera and "
      "--look-at, choose another)",
      what, format_point(spec.camera.position.value_or(fit.position)),
      format_point(spec.camera.look_at.value_or(fit.look_at)), fit.why);
}

// The outputs can be written, and replace neither the spec nor the scene file, nor the stream
// a picture.
void check_outputs(const WorkloadSpec& spec, const TraceOptions& options) {
  std::vector<NamedPath> inputs = {{"the workload spec", spec.file}};
  if (!is_builtin_scene(spec.scene)) inputs.push_back({"the scene", spec.scene});
  std::vector<NamedPath> outputs = {{"-o", options.output}};
  if (!options.preview.empty())
    for (const std::string& file : preview_files(options.preview))
      outputs.push_back({"--preview", file});
  for (const NamedPath& output : outputs)
    if (!output.path.empty()) check_output_path(output.path, output.option);
  refuse_overwriting(inputs, outputs);
}

}  // namespace

TraceResult trace_workload(const WorkloadSpec& requested, const TraceOptions& options) {
  check_outputs(requested, options);
  double start = wall_seconds();
  Scene scene = load_scene(requested.scene);
  WorkloadSpec spec = requested;
  std::vector<std::string> notes = adopt_scene_defaults(spec, scene);
  if (!spec.instances.empty() || spec.ray_masks != all_ray_masks()) {
    keep_as_instances(scene);
    set_instance_settings(scene, resolve_instance_rules(spec, scene),
                          spec.file.empty() ? spec.name : spec.file);
  }
  scene.instance_settings.still_frames = spec.warmup_frames;
  // Measured peaks of rtsim trace: 144 B a triangle kept (the scene, Embree's BVH, the
  // pipeline's scene data; an unflattened scene keeps its unique triangles and an instance
  // record and Embree instance per instance) and 87 B a pixel (G-buffer, lighting and denoiser
  // buffers, the ray queues).
  uint64_t pixels = uint64_t(spec.width) * spec.height;
  uint64_t kept = scene.flattened()
                      ? scene.triangle_count()
                      : scene.instanced.unique_triangles() + scene.instanced.instances.size();
  require_memory(kept * 160 + pixels * 96 + (uint64_t(100) << 20),
                 spec.file.empty() ? spec.name : spec.file,
                 fmt::format("tracing {} x {} pixels of a {}-triangle scene", spec.width,
                             spec.height, scene.triangle_count()),
                 "lower the resolution");
  double load_seconds = wall_seconds() - start;
  start = wall_seconds();
  std::unique_ptr<EmbreeScene> embree = embree_scene(scene, options.embree_threads);
  double build_seconds = wall_seconds() - start;
  if (!scene.instance_settings.empty()) notes.push_back(settings_note(scene, *embree));
  start = wall_seconds();

  Pipeline pipeline(spec, scene, *embree);
  if ((!spec.camera.position || !spec.camera.look_at) && spec.camera.keys.empty())
    notes.push_back(fitted_camera_note(spec, pipeline));
  if (std::string mix = ray_mix_note(pipeline.summary()); !mix.empty()) notes.push_back(mix);
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
    header.instances = scene.instance_settings;
    writer = std::make_unique<RayStreamWriter>(options.output, header);
  }
  RaySink sink(writer.get(), spec.width, spec.height, !options.preview.empty());
  uint32_t frames = pipeline.frames_to_run();
  if (options.progress)
    pipeline.on_pass = [&](uint32_t frame, PassId pass) { options.progress(frame, frames, pass); };
  FrameResults frame;
  for (uint32_t f = 0; f < frames; ++f) pipeline.run_frame(f, sink, frame);
  if (writer) writer->finish();

  TraceResult result;
  result.notes = notes;
  if (!options.preview.empty()) {
    write_preview(options.preview, pipeline, frame);
    result.images.push_back(options.preview);
    for (auto& path : write_density_images(options.preview, sink, spec.width, spec.height))
      result.images.push_back(path);
  }
  result.summary = pipeline.summary();
  result.summary.load_seconds = load_seconds;
  result.summary.build_seconds = build_seconds;
  result.summary.trace_seconds = wall_seconds() - start;
  return result;
}

}  // namespace rtsim::pipeline
