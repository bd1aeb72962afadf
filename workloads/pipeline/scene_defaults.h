// What a workload spec leaves to its scene: the scene file's own camera and lights, and a light
// when nothing lights the scene at all.
#pragma once

#include <string>
#include <vector>

#include "workloads/pipeline/spec.h"
#include "workloads/scene.h"

namespace rtsim::pipeline {

// Fills in spec from scene: a camera with neither position, look_at nor keys takes the file's
// first perspective camera whole (position, direction, up, field of view unless --fov chose
// one), or the one --camera-index names (InputError naming the scene if it has no such camera
// or it is orthographic); a spec without lights takes the file's; when neither gives a light and
// no emissive surface becomes one, a directional sun is added. Returns one line per choice made,
// for the user (stderr).
std::vector<std::string> adopt_scene_defaults(WorkloadSpec& spec, const Scene& scene);

}  // namespace rtsim::pipeline
