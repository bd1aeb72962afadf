// Scene loading: dispatch between the built-in generators and file import, and the checks every
// scene passes before anyone else sees it.
#include "workloads/scene.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/core.h>
#include <glm/geometric.hpp>

#include "traces/error.h"
#include "traces/memory_plan.h"
#include "workloads/builtin_scenes.h"
#include "workloads/scene_import.h"

namespace rtsim {
namespace {

constexpr const char* kBuiltinPrefix = "builtin:";

bool starts_with(const std::string& s, const std::string& prefix) {
  return s.compare(0, prefix.size(), prefix) == 0;
}

std::string without_prefix(const std::string& spec) {
  return starts_with(spec, kBuiltinPrefix) ? spec.substr(std::string(kBuiltinPrefix).size()) : spec;
}

bool finite(const glm::vec3& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

void check_ids(const Scene& s, const std::vector<uint32_t>& ids, uint64_t count, size_t limit,
               const char* what, const std::string& items) {
  if (ids.size() != count)
    throw_input_error(s.source, "",
                      fmt::format("{} {} ids for {} {}", ids.size(), what, count, items));
  for (size_t t = 0; t < ids.size(); ++t)
    if (ids[t] >= limit)
      throw_input_error(s.source, fmt::format("{} {}", items.substr(0, items.size() - 1), t),
                        fmt::format("{} id {} out of range", what, ids[t]));
}

void check_indices(const Scene& scene, const TriangleMesh& mesh, const std::string& prefix) {
  for (size_t t = 0; t < mesh.triangle_count(); ++t)
    for (uint32_t index : mesh.triangles[t])
      if (index >= mesh.positions.size())
        throw_input_error(scene.source, prefix + "triangle " + std::to_string(t),
                          "vertex index " + std::to_string(index) + " out of range");
}

void check_alpha(const Scene& scene, const TriangleMesh& mesh, const std::string& place) {
  if (!mesh.alpha) return;
  if (std::string problem = mesh.alpha->problem(mesh.triangle_count()); !problem.empty())
    throw_input_error(scene.source, place, problem);
}

// The cameras and lights the scene file places, in world space.
void check_cameras_and_lights(const Scene& scene) {
  auto check = [&](const std::string& place, const std::string& problem) {
    if (!problem.empty()) throw_input_error(scene.source, place, problem);
  };
  for (const SceneCamera& c : scene.cameras) {
    check("camera '" + c.name + "'", point_problem(c.position));
    check("camera '" + c.name + "' forward", direction_problem(c.forward));
    check("camera '" + c.name + "' up", direction_problem(c.up));
  }
  for (const SceneLight& l : scene.lights) {
    if (l.type != SceneLight::Type::Directional)
      check("light '" + l.name + "'", point_problem(l.position));
    check("light '" + l.name + "' direction", direction_problem(l.direction));
  }
}

// A scene that keeps only its instances: checked and bounded in world space without a
// flattened copy.
void finalize_instanced(Scene& scene) {
  const InstancedMesh& g = scene.instanced;
  std::string problem = instancing_problem(g);
  if (!problem.empty()) throw_input_error(scene.source, "instances", problem);
  if (g.instanced_triangles() >= kAnyPrim)
    throw_input_error(scene.source, "instances",
                      fmt::format("{} instanced triangles; rtsim names triangles with 32-bit ids "
                                  "(at most {})",
                                  g.instanced_triangles(), kAnyPrim - 1));
  for (size_t m = 0; m < g.meshes.size(); ++m) {
    check_indices(scene, g.meshes[m], fmt::format("mesh {} ", m));
    check_alpha(scene, g.meshes[m], fmt::format("mesh {}", m));
  }
  if (scene.mesh_material_ids.size() != g.meshes.size())
    throw_input_error(scene.source, "",
                      fmt::format("{} meshes with material ids for {} meshes",
                                  scene.mesh_material_ids.size(), g.meshes.size()));
  for (size_t m = 0; m < g.meshes.size(); ++m)
    check_ids(scene, scene.mesh_material_ids[m], g.meshes[m].triangle_count(),
              scene.materials.size(), "material", fmt::format("mesh {} triangles", m));
  check_ids(scene, scene.instance_object_ids, g.instances.size(), scene.object_names.size(),
            "object", "instances");
  std::vector<Bounds> mesh_boxes;
  for (size_t m = 0; m < g.meshes.size(); ++m) {
    for (size_t v = 0; v < g.meshes[m].positions.size(); ++v)
      if (!finite(g.meshes[m].positions[v]))
        throw_input_error(scene.source, fmt::format("mesh {} vertex {}", m, v),
                          "position " + format_point(g.meshes[m].positions[v]) + " is NaN or Inf");
    mesh_boxes.push_back(mesh_bounds(g.meshes[m]));
  }
  for (size_t i = 0; i < g.instances.size(); ++i) {
    const Instance& inst = g.instances[i];
    const std::vector<glm::vec3>& positions = g.meshes[inst.mesh].positions;
    // Vertex by vertex only where the instance's box leaves the range rtsim traces.
    Bounds box = world_box(mesh_boxes[inst.mesh], inst.to_world);
    if (!point_problem(box.lo).empty() || !point_problem(box.hi).empty())
      for (size_t v = 0; v < positions.size(); ++v)
        if (std::string problem = point_problem(inst.to_world.point(positions[v]));
            !problem.empty())
          throw_input_error(scene.source, fmt::format("instance {} vertex {}", i, v),
                            "world position " + problem);
  }
  scene.bounds = FlatTriangles(g).bounds();
  scene.fingerprint = instanced_fingerprint(g);
}

}  // namespace

std::string format_point(const glm::vec3& p) {
  auto text = [](float x) { return std::isnan(x) ? std::string("nan") : fmt::format("{}", x); };
  return "(" + text(p.x) + ", " + text(p.y) + ", " + text(p.z) + ")";
}

std::string point_problem(const glm::vec3& p) {
  if (!finite(p)) return format_point(p) + " is NaN or Inf";
  float largest = std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
  if (largest <= kMaxSceneCoordinate) return "";
  return fmt::format(
      "{} is beyond +-{:g}, the range rtsim traces (Embree's rays reach +-1.8e18; cameras and "
      "ray offsets around the scene must stay inside)",
      format_point(p), kMaxSceneCoordinate);
}

std::string direction_problem(const glm::vec3& d) {
  if (!finite(d)) return format_point(d) + " is NaN or Inf";
  float largest = std::max({std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)});
  if (largest > kMaxSceneCoordinate)
    return fmt::format("{} has a component beyond +-{:g}; give a shorter vector", format_point(d),
                       kMaxSceneCoordinate);
  if (!(glm::length(d) >= 1.0f / kMaxSceneCoordinate))
    return fmt::format("must not be zero or shorter than {:g}", 1.0f / kMaxSceneCoordinate);
  return "";
}

bool is_builtin_scene(const std::string& spec) {
  if (starts_with(spec, kBuiltinPrefix)) return true;
  std::string name = spec.substr(0, spec.find(':'));
  return name == "cornell" || name == "pica" || name == "grid" || name == "foliage" ||
         name == "forest" || name == "city" || name == "hardcases";
}

std::vector<std::string> builtin_scene_names() {
  return {"cornell", "pica", "grid:N", "foliage:N", "forest:N", "city:N", "hardcases"};
}

Scene load_scene(const std::string& spec) {
  Scene scene = is_builtin_scene(spec) ? builtin::make_builtin_scene(without_prefix(spec))
                                       : import_scene_file(spec);
  finalize_scene(scene);
  return scene;
}

void finalize_scene(Scene& scene) {
  check_cameras_and_lights(scene);
  if (!scene.flattened() && !scene.instanced.instances.empty()) return finalize_instanced(scene);
  const TriangleMesh& mesh = scene.mesh;
  if (mesh.triangle_count() == 0) throw_input_error(scene.source, "", "the scene has no triangles");
  for (size_t v = 0; v < mesh.positions.size(); ++v)
    if (std::string problem = point_problem(mesh.positions[v]); !problem.empty())
      throw_input_error(scene.source, "vertex " + std::to_string(v), "position " + problem);
  check_indices(scene, mesh, "");
  check_alpha(scene, mesh, "");
  check_ids(scene, scene.material_ids, mesh.triangle_count(), scene.materials.size(), "material",
            "triangles");
  check_ids(scene, scene.object_ids, mesh.triangle_count(), scene.object_names.size(), "object",
            "triangles");
  scene.bounds = mesh_bounds(mesh);
  scene.fingerprint = mesh_fingerprint(mesh);
}

TriangleAttributes Scene::attributes(const FlatTriangles& triangles, uint64_t tri) const {
  if (flattened())
    return {tri < material_ids.size() ? material_ids[tri] : 0,
            tri < object_ids.size() ? object_ids[tri] : 0};
  FlatTriangles::Place at = triangles.locate(tri);
  return {instance_material(at.instance, at.prim), instance_object_ids[at.instance]};
}

uint32_t Scene::instance_material(size_t i, uint32_t prim) const {
  uint32_t own = own_material(i);
  return own != kMeshMaterials ? own : mesh_material_ids[instanced.instances[i].mesh][prim];
}

const TriangleMesh& flat_mesh(Scene& scene) {
  if (scene.flattened()) return scene.mesh;
  // The flattened arrays: 12 B a vertex, 12 B a triangle and its two ids.
  uint64_t bytes = 0;
  for (const Instance& inst : scene.instanced.instances) {
    const TriangleMesh& mesh = scene.instanced.meshes[inst.mesh];
    bytes += 12 * mesh.positions.size() + 20 * mesh.triangle_count();
  }
  require_memory(bytes, scene.source,
                 fmt::format("flattening {} instanced triangles", scene.triangle_count()),
                 "keep its instances (bvh.instancing = \"auto\" or \"two_level\", no --flatten)");
  scene.mesh = flatten(scene.instanced).mesh;
  for (size_t i = 0; i < scene.instanced.instances.size(); ++i) {
    auto triangles =
        uint32_t(scene.instanced.meshes[scene.instanced.instances[i].mesh].triangle_count());
    for (uint32_t prim = 0; prim < triangles; ++prim)
      scene.material_ids.push_back(scene.instance_material(i, prim));
    scene.object_ids.insert(scene.object_ids.end(), triangles, scene.instance_object_ids[i]);
  }
  return scene.mesh;
}

std::unique_ptr<EmbreeScene> embree_scene(const Scene& scene, int threads) {
  if (scene.flattened()) return std::make_unique<EmbreeScene>(scene.mesh, threads);
  return std::make_unique<EmbreeScene>(scene.instanced, scene.instance_settings, threads);
}

void keep_as_instances(Scene& scene) {
  if (!scene.flattened()) return;
  InstancedMesh& g = scene.instanced;
  if (g.instances.empty())
    throw_input_error(scene.source, "",
                      "the scene is one mesh without instances: instance masks and motion need "
                      "a scene of instances (glTF or OBJ nodes, pica, forest:N, city:N)");
  // A file's instances take their materials and objects from the flattened copy; pica keeps
  // both views from the start.
  if (scene.mesh_material_ids.size() != g.meshes.size()) {
    std::vector<uint64_t> offsets = flat_offsets(g);
    scene.mesh_material_ids.assign(g.meshes.size(), {});
    for (size_t m = 0; m < g.meshes.size(); ++m)
      scene.mesh_material_ids[m].assign(g.meshes[m].triangle_count(), 0);
    scene.instance_object_ids.assign(g.instances.size(), 0);
    for (size_t i = 0; i < g.instances.size(); ++i) {
      std::vector<uint32_t>& materials = scene.mesh_material_ids[g.instances[i].mesh];
      std::copy_n(scene.material_ids.begin() + int64_t(offsets[i]), materials.size(),
                  materials.begin());
      scene.instance_object_ids[i] = scene.object_ids[offsets[i]];
    }
  }
  scene.mesh = {};
  scene.material_ids.clear();
  scene.object_ids.clear();
}

void set_instance_settings(Scene& scene, const InstanceSettings& settings,
                           const std::string& where) {
  if (settings.empty()) return;
  keep_as_instances(scene);
  InstancedMesh& g = scene.instanced;
  if (std::string problem = settings_problem(settings, g.instances.size()); !problem.empty())
    throw_input_error(where, "instance settings", problem);
  scene.instance_settings = settings;
  apply_masks(g, settings);
  std::vector<Bounds> mesh_boxes;
  for (const TriangleMesh& mesh : g.meshes) mesh_boxes.push_back(mesh_bounds(mesh));
  for (uint32_t f = 0; settings.animated() && f < settings.frames; ++f)
    for (const auto& [instance, motion] : settings.moving) {
      const Instance& placed = g.instances[instance];
      Bounds box =
          world_box(mesh_boxes[placed.mesh],
                    pose_at(placed.to_world, settings.motions[motion], f, settings.frames));
      if (std::string problem = point_problem(box.lo) + point_problem(box.hi); !problem.empty())
        throw_input_error(where, fmt::format("instance {} in frame {}", instance, f),
                          "its motion carries it out of range: " + problem);
    }
}

Scene load_stream_scene(const std::string& stream, const StreamHeader& header,
                        const std::string& scene_override) {
  std::string spec = scene_override.empty() ? header.scene_source : scene_override;
  if (spec.empty()) throw_input_error(stream, "header", "no scene named; pass --scene");
  namespace fs = std::filesystem;
  std::error_code error;
  if (scene_override.empty() && !is_builtin_scene(spec) && !fs::exists(spec, error)) {
    // A relative path was relative to where the stream was traced: try beside the stream too.
    fs::path beside = fs::path(stream).parent_path() / spec;
    if (fs::path(spec).is_relative() && fs::exists(beside, error))
      spec = beside.string();
    else
      throw_input_error(stream, "header",
                        "its scene " + spec + " is not found (from this folder" +
                            (fs::path(spec).is_relative() ? " nor from the stream's" : "") +
                            "); pass --scene FILE to name it");
  }
  Scene scene = load_scene(spec);
  if (scene.fingerprint != header.scene_fingerprint)
    throw_input_error(stream, "header",
                      fmt::format("scene fingerprint {:016x} does not match scene {} ({:016x})",
                                  header.scene_fingerprint, spec, scene.fingerprint));
  set_instance_settings(scene, header.instances, stream);
  return scene;
}

}  // namespace rtsim
