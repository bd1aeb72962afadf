// rtsim scene-info FILE|BUILTIN: what a scene holds, and its fingerprint; with --bvh, the BVH a
// hardware config would simulate over it (one level or two) and its bytes.
#include <fmt/core.h>

#include "app/commands.h"
#include "model/config/hw_config.h"
#include "reports/phase_progress.h"
#include "workloads/scene.h"

namespace rtsim::app {

void add_scene_info_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("scene-info", "Print a scene's counts, bounds and fingerprint");
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
  cmd->add_option("--config", o->config, "Hardware config for --bvh (.toml; configs/)");
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
    const InstancedMesh& inst = scene.instanced;
    if (inst.instances.empty())
      fmt::print("instances    none (one flat mesh)\n");
    else
      fmt::print("instances    {} of {} unique meshes: {} unique triangles, {} instanced\n",
                 inst.instances.size(), inst.meshes.size(), inst.unique_triangles(),
                 inst.instanced_triangles());
    fmt::print("materials    {}\n", scene.materials.size());
    const Bounds& b = scene.bounds;
    fmt::print("bounds       [{:g}, {:g}, {:g}] .. [{:g}, {:g}, {:g}]\n", b.lo.x, b.lo.y, b.lo.z,
               b.hi.x, b.hi.y, b.hi.z);
    for (const SceneCamera& c : scene.cameras)
      fmt::print(
          "camera       '{}' at [{:g}, {:g}, {:g}] looking [{:g}, {:g}, {:g}], {:.3g} degrees "
          "high\n",
          c.name, c.position.x, c.position.y, c.position.z, c.forward.x, c.forward.y, c.forward.z,
          c.yfov_degrees);
    for (const SceneLight& l : scene.lights)
      fmt::print("light        '{}' {} at [{:g}, {:g}, {:g}]\n", l.name,
                 l.type == SceneLight::Type::Directional ? "directional"
                 : l.type == SceneLight::Type::Spot      ? "spot"
                                                         : "point",
                 l.position.x, l.position.y, l.position.z);
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
