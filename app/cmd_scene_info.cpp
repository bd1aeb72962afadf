// rtsim scene-info FILE|BUILTIN: what a scene holds, and its fingerprint.
#include <fmt/core.h>

#include "app/commands.h"
#include "workloads/scene.h"

namespace rtsim::app {

void add_scene_info_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("scene-info", "Print a scene's counts, bounds and fingerprint");
  auto spec = std::make_shared<std::string>();
  std::string builtins;
  for (const auto& name : builtin_scene_names()) builtins += (builtins.empty() ? "" : ", ") + name;
  cmd->add_option("scene", *spec,
                  "Scene file (OBJ, glTF, GLB, PLY, OFF, STL) or built-in: " + builtins)
      ->required();
  cmd->callback([spec, &exit_code] {
    Scene scene = load_scene(*spec);
    fmt::print("scene        {}\n", scene.source);
    fmt::print("triangles    {}\n", scene.triangle_count());
    fmt::print("vertices     {}\n", scene.mesh.positions.size());
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
    exit_code = 0;
  });
}

}  // namespace rtsim::app
