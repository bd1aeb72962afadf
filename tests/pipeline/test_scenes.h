// Hand-made scenes and frame set-ups for pass tests: a few quads with chosen materials, an
// Embree scene over them, and a camera, so each pass can be checked in isolation.
#pragma once

#include <glm/geometric.hpp>
#include <memory>
#include <string>
#include <vector>

#include "traces/embree_scene.h"
#include "workloads/pipeline/context.h"
#include "workloads/pipeline/gbuffer.h"
#include "workloads/pipeline/pass_camera.h"
#include "workloads/pipeline/ray_sink.h"
#include "workloads/pipeline/samples.h"
#include "workloads/scene.h"

namespace rtsim::pipeline::test {

// Adds quad a-b-c-d (two triangles, wound a-b-c, a-c-d) as a new object with a new material.
inline void add_quad(Scene& s, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d,
                     const Material& m, const std::string& object) {
  auto base = uint32_t(s.mesh.positions.size());
  s.mesh.positions.insert(s.mesh.positions.end(), {a, b, c, d});
  s.mesh.triangles.push_back({base, base + 1, base + 2});
  s.mesh.triangles.push_back({base, base + 2, base + 3});
  auto mat = uint32_t(s.materials.size());
  s.materials.push_back(m);
  auto obj = uint32_t(s.object_names.size());
  s.object_names.push_back(object);
  for (int i = 0; i < 2; ++i) {
    s.material_ids.push_back(mat);
    s.object_ids.push_back(obj);
  }
}

inline Material material(const std::string& name, float roughness) {
  Material m;
  m.name = name;
  m.roughness = roughness;
  return m;
}

// A 10 x 10 wall in the plane z = 0, facing +z, centred on the origin.
inline void add_wall(Scene& s, const Material& m, const std::string& name = "wall") {
  add_quad(s, {-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}, m, name);
}

inline void finish(Scene& s) {
  s.source = "test";
  s.fingerprint = mesh_fingerprint(s.mesh);
  s.bounds = mesh_bounds(s.mesh);
}

// Everything a pass needs, over one scene, with a camera at (0, 0, 5) looking at the origin
// whose view is filled by the wall.
struct Fixture {
  Scene scene;
  WorkloadSpec spec;
  std::unique_ptr<MaterialTable> materials;
  std::unique_ptr<EmbreeScene> embree;
  std::unique_ptr<SceneContext> ctx;

  Fixture(Scene s, std::vector<LightSpec> lights, uint32_t width = 32, uint32_t height = 24)
      : scene(std::move(s)) {
    finish(scene);
    spec.width = width;
    spec.height = height;
    spec.lights = std::move(lights);
    spec.passes = preset_passes("pica-pica");
    materials = std::make_unique<MaterialTable>(assign_materials(scene, spec.materials));
    embree = std::make_unique<EmbreeScene>(scene.mesh, 1);
    ctx = std::make_unique<SceneContext>(
        SceneContext{scene, *materials, *embree, resolve_lights(spec, scene, *materials),
                     glm::vec3(0.0f), glm::length(scene.bounds.extent())});
  }

  Fixture(const Fixture&) = delete;
  Fixture& operator=(const Fixture&) = delete;

  FrameContext frame(uint32_t index = 0) const {
    Camera cam = Camera::look_at({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 60.0f, spec.width, spec.height);
    return FrameContext{*ctx, spec.passes, cam, index, spec.seed, spec.width, spec.height};
  }

  GBuffer gbuffer(const FrameContext& f) const {
    return run_camera_pass(f, regular_samples(spec.width, spec.height, {0, 0}), nullptr);
  }
};

// Rays a pass shot, with the triangle each left from.
struct RecordedRays {
  std::vector<Ray> rays;
  std::vector<uint32_t> origins;
};

inline RaySink recording_sink(const Fixture& fx, RecordedRays& out) {
  RaySink sink(nullptr, fx.spec.width, fx.spec.height, false);
  sink.observer = [&out](const Ray& r, PassId, uint32_t origin) {
    out.rays.push_back(r);
    out.origins.push_back(origin);
  };
  return sink;
}

inline LightSpec point_light(glm::vec3 position, float intensity = 10.0f) {
  LightSpec l;
  l.type = LightType::Point;
  l.position = position;
  l.intensity = intensity;
  return l;
}

}  // namespace rtsim::pipeline::test
