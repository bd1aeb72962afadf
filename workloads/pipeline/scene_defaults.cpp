#include "workloads/pipeline/scene_defaults.h"

#include <optional>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "workloads/pipeline/materials.h"
#include "workloads/pipeline/sampling.h"
#include "traces/error.h"

namespace rtsim::pipeline {
namespace {

std::string vec(const glm::vec3& v) {
  return fmt::format("({:.3g}, {:.3g}, {:.3g})", v.x, v.y, v.z);
}

LightSpec light_spec(const SceneLight& l) {
  LightSpec s;
  s.type = l.type == SceneLight::Type::Directional ? LightType::Directional
           : l.type == SceneLight::Type::Spot      ? LightType::Spot
                                                   : LightType::Point;
  if (s.type != LightType::Directional) s.position = l.position;
  s.direction = l.direction;
  s.color = l.color;
  s.cone_angle = l.outer_cone_degrees;
  return s;
}

bool has_emissive_surface(const WorkloadSpec& spec, const Scene& scene) {
  if (!spec.lights_from_emission) return false;
  return assign_materials(scene, spec.materials).any_emissive();
}

// "camera 1 'top' of level.gltf"
std::string camera_name(const Scene& scene, size_t index) {
  return fmt::format("camera {} '{}' of {}", index, scene.cameras[index].name, scene.source);
}

// The file camera a spec adopts: --camera-index's (InputError naming the scene if there is no
// such camera, or it is orthographic), else the first perspective one, if the spec leaves the
// view open. Notes an orthographic camera passed over.
std::optional<size_t> file_camera(const CameraSpec& camera, const Scene& scene,
                                  std::vector<std::string>& notes) {
  const size_t count = scene.cameras.size();
  if (camera.file_camera) {
    size_t index = *camera.file_camera;
    if (index >= count)
      throw_input_error(scene.source, "--camera-index " + std::to_string(index),
                        count == 0 ? std::string("the scene has no cameras")
                                   : fmt::format("the scene has {} camera{} (0 to {}; rtsim "
                                                 "scene-info lists them)",
                                                 count, count == 1 ? "" : "s", count - 1));
    if (scene.cameras[index].orthographic)
      throw_input_error(scene.source, "--camera-index " + std::to_string(index),
                        "camera '" + scene.cameras[index].name +
                            "' is orthographic; rtsim's camera is a pinhole (perspective): "
                            "choose a perspective camera or give --camera and --look-at");
    return index;
  }
  if (camera.position || camera.look_at || !camera.keys.empty()) return std::nullopt;
  for (size_t i = 0; i < count; ++i) {
    if (!scene.cameras[i].orthographic) return i;
    notes.push_back(camera_name(scene, i) +
                    " is orthographic: not adopted (rtsim's camera is a pinhole)");
  }
  return std::nullopt;
}

}  // namespace

std::vector<std::string> adopt_scene_defaults(WorkloadSpec& spec, const Scene& scene) {
  std::vector<std::string> notes;
  CameraSpec& camera = spec.camera;
  if (std::optional<size_t> index = file_camera(camera, scene, notes)) {
    const SceneCamera& c = scene.cameras[*index];
    camera.position = c.position;
    camera.look_at = c.position + c.forward;
    camera.keys.clear();
    camera.up = c.up;
    if (!camera.fov_chosen) camera.fov = c.yfov_degrees;
    notes.push_back(fmt::format("{}: at {} looking along {}, {:.3g} degrees high{}",
                                camera_name(scene, *index), vec(c.position), vec(c.forward),
                                camera.fov, camera.fov_chosen ? " (--fov)" : ""));
  }
  if (spec.lights.empty() && !scene.lights.empty()) {
    for (const SceneLight& l : scene.lights) spec.lights.push_back(light_spec(l));
    notes.push_back(fmt::format("{} light(s) of {}", scene.lights.size(), scene.source));
  }
  if (spec.lights.empty() && !has_emissive_surface(spec, scene)) {
    Basis basis(glm::normalize(camera.up));
    LightSpec sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(-basis.n + 0.45f * basis.t + 0.3f * basis.b);
    sun.angular_diameter = 0.5f;
    spec.lights.push_back(sun);
    notes.push_back(fmt::format(
        "no light in the spec or in {}: added a directional sun pointing {}, 0.5 degrees "
        "wide (set [[light]] in a workload spec to choose)",
        scene.source, vec(sun.direction)));
  }
  return notes;
}

}  // namespace rtsim::pipeline
