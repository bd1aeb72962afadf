#include "workloads/pipeline/workload.h"

#include <filesystem>

#include "traces/error.h"
#include "workloads/scene.h"

namespace rtsim::pipeline {

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

}  // namespace rtsim::pipeline
