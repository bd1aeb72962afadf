#include "workloads/pipeline/workload.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "traces/error.h"
#include "workloads/scene.h"

namespace rtsim::pipeline {

namespace {

// "X,Y,Z" as three finite numbers; a point in the range of scene points (scene.h), or a
// direction that can be normalized.
std::optional<glm::vec3> parse_vector(const std::string& option, const std::string& text,
                                      bool direction) {
  if (text.empty()) return std::nullopt;
  glm::vec3 v;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%f,%f,%f%c", &v.x, &v.y, &v.z, &tail) != 3 ||
      !std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
    throw InputError(option + " " + text + ": expected three numbers X,Y,Z, e.g. 0,1.5,4");
  std::string problem = direction ? direction_problem(v) : point_problem(v);
  if (!problem.empty()) throw InputError(option + " " + text + ": " + problem);
  return v;
}

// The view the overrides leave must have a direction and an up.
void check_overridden_view(const CameraSpec& c, const SpecOverrides& o) {
  if (!c.position || !c.look_at) return;
  ViewProblem problem = view_problem(*c.position, *c.look_at, c.up);
  if (problem == ViewProblem::NoDirection)
    throw InputError(std::string(o.camera ? "--camera" : "--look-at") +
                     ": the camera position equals the look-at point (--camera, --look-at or "
                     "the spec's [camera]): the camera has no view direction");
  if (problem == ViewProblem::NoUp)
    throw InputError(
        "--up: parallel to the view direction (camera to look-at point): the image has no up; "
        "choose another --up");
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
  if (o.camera || o.look_at || o.camera_index) spec.camera.keys.clear();
  if (o.camera_index) {
    spec.camera.position.reset();
    spec.camera.look_at.reset();
    spec.camera.file_camera = o.camera_index;
  }
  if (o.fov) {
    spec.camera.fov = *o.fov;
    spec.camera.fov_chosen = true;
  }
  if (o.camera) spec.camera.position = o.camera;
  if (o.look_at) spec.camera.look_at = o.look_at;
  if (o.up) spec.camera.up = *o.up;
  if (o.camera || o.look_at || o.up) check_overridden_view(spec.camera, o);
}

SpecOverrides make_overrides(const OverrideText& text) {
  SpecOverrides o;
  if (!text.resolution.empty()) {
    uint32_t w = 0, h = 0;
    if (!parse_resolution(text.resolution, w, h))
      throw InputError("--resolution " + text.resolution + ": expected WxH, e.g. 1920x1080");
    o.width = w;
    o.height = h;
  }
  if (text.frames > 0) o.frames = text.frames;
  o.seed = text.seed;
  if (!text.scene.empty()) o.scene = text.scene;
  o.camera = parse_vector("--camera", text.camera, false);
  o.look_at = parse_vector("--look-at", text.look_at, false);
  o.up = parse_vector("--up", text.up, true);
  if (text.camera_index && (o.camera || o.look_at))
    throw InputError(
        "--camera-index: cannot be combined with --camera or --look-at (a file "
        "camera is a whole view; --fov and --up may change it)");
  o.camera_index = text.camera_index;
  if (text.fov) {
    if (!(*text.fov >= kMinFov && *text.fov <= kMaxFov))
      throw InputError(
          fmt::format("--fov {:g}: expected a vertical field of view from {:g} to "
                      "{:g} degrees",
                      *text.fov, kMinFov, kMaxFov));
    o.fov = float(*text.fov);
  }
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
