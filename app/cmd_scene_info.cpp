// rtsim scene-info FILE|BUILTIN: what a scene holds, and its fingerprint; with --bvh, the BVH a
// hardware config would simulate over it (one level or two) and its bytes.
#include <algorithm>

#include <fmt/core.h>
#include <glm/vec3.hpp>

#include "app/commands.h"
#include "model/config/hw_config.h"
#include "reports/phase_progress.h"
#include "workloads/scene.h"

namespace rtsim::app {
namespace {

std::string vec(const glm::vec3& v) {
  return fmt::format("[{:g}, {:g}, {:g}]", v.x, v.y, v.z);
}

// Object names, as [[material]] and [[instances]] rules match them: quoted, wrapped at 100
// columns, the first kMaxNames of them.
void print_names(const std::vector<std::string>& names) {
  constexpr size_t kMaxNames = 200;
  std::string line = "  names     ";
  for (size_t i = 0; i < names.size() && i < kMaxNames; ++i) {
    std::string item = " '" + names[i] + "'" + (i + 1 < names.size() ? "," : "");
    if (line.size() + item.size() > 100 && line.size() > 12) {
      fmt::print("{}\n", line);
      line = "           ";
    }
    line += item;
  }
  if (names.size() > kMaxNames) line += fmt::format(" ... and {} more", names.size() - kMaxNames);
  if (!names.empty()) fmt::print("{}\n", line);
}

std::string describe_material(const Material& m) {
  std::string out = fmt::format("'{}': base colour {}, roughness {:g}, metalness {:g}", m.name,
                                vec(m.base_color), m.roughness, m.metalness);
  if (m.layers > 1) out += fmt::format(", {} layers", m.layers);
  if (m.transmission > 0)
    out += fmt::format(", transmission {:g} (ior {:g})", m.transmission, m.ior);
  if (m.translucency > 0) out += fmt::format(", translucency {:g}", m.translucency);
  if (m.emission != glm::vec3(0.0f)) out += ", emission " + vec(m.emission);
  return out;
}

std::string describe_camera(const SceneCamera& c) {
  std::string where =
      fmt::format("at {} looking {}, up {}", vec(c.position), vec(c.forward), vec(c.up));
  if (c.orthographic)
    return fmt::format(
        "'{}' orthographic {}: a view box {:g} x {:g} wide and high (not "
        "adopted: rtsim's camera is a pinhole)",
        c.name, where, 2.0f * c.xmag, 2.0f * c.ymag);
  return fmt::format("'{}' perspective {}, {:.3g} degrees high", c.name, where, c.yfov_degrees);
}

// glTF's KHR_lights_punctual: colour times intensity (candela; lux for a directional light).
std::string describe_light(const SceneLight& l) {
  float intensity = std::max({l.color.x, l.color.y, l.color.z});
  glm::vec3 colour = intensity > 0.0f ? l.color / intensity : l.color;
  std::string shine =
      fmt::format("intensity {:g} {}, colour {}", intensity,
                  l.type == SceneLight::Type::Directional ? "lux" : "cd", vec(colour));
  switch (l.type) {
    case SceneLight::Type::Directional:
      return fmt::format("'{}' directional, direction {}, {}", l.name, vec(l.direction), shine);
    case SceneLight::Type::Spot:
      return fmt::format("'{}' spot at {}, direction {}, cone {:g} degrees, {}", l.name,
                         vec(l.position), vec(l.direction), l.outer_cone_degrees, shine);
    case SceneLight::Type::Point: break;
  }
  return fmt::format("'{}' point at {}, {}", l.name, vec(l.position), shine);
}

}  // namespace

void add_scene_info_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "scene-info",
      "Print a scene's counts, objects, materials, cameras, lights, bounds and fingerprint");
  struct Options {
    std::string spec, config;
    std::vector<std::string> sets;
    bool bvh = false;
  };
  auto o = std::make_shared<Options>();
  std::string builtins;
  for (const auto& name : builtin_scene_names()) builtins += (builtins.empty() ? "" : ", ") + name;
  cmd->add_option("scene", o->spec,
                  "Scene file (OBJ, glTF, GLB, PLY, OFF, STL) or built-in: " + builtins)
      ->required();
  cmd->add_flag("--bvh", o->bvh, "Also build the BVH the hardware config simulates; its bytes");
  cmd->add_option("--config", o->config, "Hardware config for --bvh: " + kConfigForms);
  cmd->add_option("--set", o->sets, "Override a config key for --bvh: --set bvh.instancing=flatten")
      ->allow_extra_args(false);
  cmd->callback([o, &exit_code] {
    HwConfig config = load_hw_config(o->config, o->sets);
    Scene scene = load_scene(o->spec);
    fmt::print("scene        {}\n", scene.source);
    fmt::print("triangles    {}\n", scene.triangle_count());
    if (scene.flattened()) {
      fmt::print("vertices     {}\n", scene.mesh.positions.size());
    } else {
      size_t vertices = 0;
      for (const TriangleMesh& mesh : scene.instanced.meshes) vertices += mesh.positions.size();
      fmt::print("vertices     {} in the unique meshes (no flattened copy is kept)\n", vertices);
    }
    fmt::print("objects      {}\n", scene.object_names.size());
    print_names(scene.object_names);
    const InstancedMesh& inst = scene.instanced;
    if (inst.instances.empty())
      fmt::print("instances    none (one flat mesh)\n");
    else
      fmt::print("instances    {} of {} unique meshes: {} unique triangles, {} instanced\n",
                 inst.instances.size(), inst.meshes.size(), inst.unique_triangles(),
                 inst.instanced_triangles());
    fmt::print("materials    {}\n", scene.materials.size());
    for (size_t m = 0; m < scene.materials.size(); ++m)
      fmt::print("  {:<11}{}\n", m, describe_material(scene.materials[m]));
    const Bounds& b = scene.bounds;
    fmt::print("bounds       [{:g}, {:g}, {:g}] .. [{:g}, {:g}, {:g}]\n", b.lo.x, b.lo.y, b.lo.z,
               b.hi.x, b.hi.y, b.hi.z);
    fmt::print("cameras      {}{}\n", scene.cameras.size(),
               scene.cameras.empty() ? "" : " (trace, run: --camera-index N)");
    for (size_t c = 0; c < scene.cameras.size(); ++c)
      fmt::print("  {:<11}{}\n", c, describe_camera(scene.cameras[c]));
    fmt::print("lights       {}\n", scene.lights.size());
    for (size_t l = 0; l < scene.lights.size(); ++l)
      fmt::print("  {:<11}{}\n", l, describe_light(scene.lights[l]));
    fmt::print("fingerprint  {:016x}\n", scene.fingerprint);
    if (o->bvh) {
      TwoLevelBvh bvh = reports::build_scene_bvh(scene, config.bvh, true);
      fmt::print("bvh          {}, {}: {} B, {}\n", bvh.bottom.empty() ? "one level" : "two levels",
                 describe(config.bvh), bvh.total_bytes(), reports::bvh_summary(bvh));
    }
    exit_code = 0;
  });
}

}  // namespace rtsim::app
