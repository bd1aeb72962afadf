// Finding a workload from the command line: a spec file or a scene, and the command-line
// overrides of its settings.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "workloads/pipeline/spec.h"

namespace rtsim::pipeline {

// Command-line overrides of a spec; unset fields keep the spec's value. A new scene also makes
// the camera automatic (the spec's lights and material rules stay); a camera position or look-at
// point replaces the spec's camera path, and so does a file camera (camera_index: the scene
// file's camera N, whole); fov replaces the field of view, also a file camera's. A view without
// a direction or an up is InputError naming the options.
struct SpecOverrides {
  std::optional<uint32_t> frames, width, height;
  std::optional<uint64_t> seed;
  std::optional<std::string> scene;
  std::optional<glm::vec3> camera, look_at, up;
  std::optional<uint32_t> camera_index;
  std::optional<float> fov;
};
void apply_overrides(WorkloadSpec& spec, const SpecOverrides& overrides);

// The overrides as command-line text; "" and 0 leave a setting unset.
struct OverrideText {
  std::string resolution;  // "WxH"
  uint32_t frames = 0;
  std::optional<uint64_t> seed{};
  std::string scene{};
  std::string camera{}, look_at{}, up{};   // "X,Y,Z"
  std::optional<uint32_t> camera_index{};  // --camera-index N
  std::optional<double> fov{};             // --fov DEG
};
// InputError naming the option if a value is malformed, out of range (--fov: 1 to 179 degrees,
// as camera.fov) or combined with one it contradicts (--camera-index with --camera or
// --look-at).
SpecOverrides make_overrides(const OverrideText& text);

// A spec file (.toml), or a scene (built-in name or file) with the default spec.
WorkloadSpec load_workload(const std::string& workload);

}  // namespace rtsim::pipeline
