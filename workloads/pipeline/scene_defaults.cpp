#include "workloads/pipeline/scene_defaults.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "workloads/pipeline/materials.h"
#include "workloads/pipeline/sampling.h"

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

}  // namespace

std::vector<std::string> adopt_scene_defaults(WorkloadSpec& spec, const Scene& scene) {
  std::vector<std::string> notes;
  CameraSpec& camera = spec.camera;
  if (!camera.position && !camera.look_at && camera.keys.empty() && !scene.cameras.empty()) {
    const SceneCamera& c = scene.cameras.front();
    camera.position = c.position;
    camera.look_at = c.position + c.forward;
    camera.up = c.up;
    camera.fov = c.yfov_degrees;
    notes.push_back(fmt::format("camera '{}' of {}: at {} looking along {}, {:.3g} degrees high",
                                c.name, scene.source, vec(c.position), vec(c.forward),
                                c.yfov_degrees));
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
