// Scene loading: dispatch between the built-in generators and file import, and the checks every
// scene passes before anyone else sees it.
#include "workloads/scene.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/core.h>

#include "traces/error.h"
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

void check_ids(const Scene& s, const std::vector<uint32_t>& ids, size_t limit, const char* what) {
  if (ids.size() != s.triangle_count())
    throw_input_error(s.source, "",
                      std::to_string(ids.size()) + " " + what + " ids for " +
                          std::to_string(s.triangle_count()) + " triangles");
  for (size_t t = 0; t < ids.size(); ++t)
    if (ids[t] >= limit)
      throw_input_error(s.source, "triangle " + std::to_string(t),
                        std::string(what) + " id " + std::to_string(ids[t]) + " out of range");
}

}  // namespace

bool is_builtin_scene(const std::string& spec) {
  if (starts_with(spec, kBuiltinPrefix)) return true;
  std::string name = spec.substr(0, spec.find(':'));
  return name == "cornell" || name == "pica" || name == "grid" || name == "foliage" ||
         name == "forest" || name == "hardcases";
}

std::vector<std::string> builtin_scene_names() {
  return {"cornell", "pica", "grid:N", "foliage:N", "forest:N", "hardcases"};
}

Scene load_scene(const std::string& spec) {
  Scene scene = is_builtin_scene(spec) ? builtin::make_builtin_scene(without_prefix(spec))
                                       : import_scene_file(spec);
  finalize_scene(scene);
  return scene;
}

void finalize_scene(Scene& scene) {
  const TriangleMesh& mesh = scene.mesh;
  if (mesh.triangle_count() == 0) throw_input_error(scene.source, "", "the scene has no triangles");
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const glm::vec3& p = mesh.positions[v];
    if (!finite(p))
      throw_input_error(scene.source, "vertex " + std::to_string(v), "position is NaN or Inf");
    float largest = std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
    if (largest > kMaxSceneCoordinate)
      throw_input_error(
          scene.source, "vertex " + std::to_string(v),
          fmt::format("coordinate {:g} is beyond +-{:g}, the range rtsim traces (cameras and ray "
                      "offsets must stay inside Embree's +-1.8e18); scale the scene down",
                      largest, kMaxSceneCoordinate));
  }
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    for (uint32_t index : mesh.triangles[t])
      if (index >= mesh.positions.size())
        throw_input_error(scene.source, "triangle " + std::to_string(t),
                          "vertex index " + std::to_string(index) + " out of range");
  }
  check_ids(scene, scene.material_ids, scene.materials.size(), "material");
  check_ids(scene, scene.object_ids, scene.object_names.size(), "object");
  scene.bounds = mesh_bounds(mesh);
  scene.fingerprint = mesh_fingerprint(mesh);
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
  return scene;
}

}  // namespace rtsim
