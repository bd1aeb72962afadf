// Embree 3 (robust mode) over a TriangleMesh: the reference that finds surfaces for the
// pipeline passes (workloads/) and checks every ray of the model (model/verify/).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "traces/instance_settings.h"
#include "traces/ray.h"

struct RTCDeviceTy;
struct RTCSceneTy;
struct RTCGeometryTy;

namespace rtsim {

class EmbreeScene {
 public:
  // threads = 0 lets Embree choose; 1 makes the build single-threaded too.
  explicit EmbreeScene(const TriangleMesh& mesh, int threads = 0);
  // Two levels: one Embree scene per unique mesh, placed by instance geometries (Embree's
  // instancing); hits name the instance and the triangle of its mesh. Call
  // instancing_problem() first: this trusts the geometry.
  explicit EmbreeScene(const InstancedMesh& geometry, int threads = 0);
  // Two levels under a workload's instance settings: instance masks are Embree's geometry masks
  // and each ray carries its type's inclusion mask; with motion, one top level per frame (the
  // unique meshes shared) and a ray is traced in its frame's (InstanceSettings::pose_frame).
  EmbreeScene(const InstancedMesh& geometry, const InstanceSettings& settings, int threads = 0);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // Closest hit in [tmin, tmax] for a closest-hit query; for an any-hit query, some hit
  // reported as prim = kAnyPrim, t = tmax (Embree does not say which triangle).
  Hit trace(const Ray& ray) const;
  // met_alpha, where given, is set to whether the query met an alpha-tested candidate: the
  // alpha test ran for it at least once, whatever it decided (never for a forced-opaque ray).
  // Which candidates a query meets beyond its result follows Embree's traversal order.
  Hit intersect(const Ray& ray, bool* met_alpha = nullptr) const;  // closest, whatever ray.query
  bool occluded(const Ray& ray, bool* met_alpha = nullptr) const;  // any hit in [tmin, tmax]

  // Host seconds Embree took to build each frame's top level (one entry without motion).
  const std::vector<double>& top_build_seconds() const { return top_seconds_; }

 private:
  void open_device(int threads);
  // A top level over instances: a new geometry for each moving instance and each one without
  // one yet, the others' reused (a static instance is shared by every frame's top level).
  RTCSceneTy* build_top(const std::vector<Instance>& instances,
                        std::vector<RTCGeometryTy*>& geometries, const std::vector<bool>& moving);
  RTCSceneTy* scene_of(const Ray& ray) const;

  RTCDeviceTy* device_ = nullptr;
  RTCSceneTy* scene_ = nullptr;            // one level, or frame 0's top level
  std::vector<RTCSceneTy*> frame_scenes_;  // with motion: frames 1.. (top levels)
  std::vector<RTCSceneTy*> mesh_scenes_;   // instanced: the bottom level
  InstanceSettings settings_;  // one level: the defaults (every ray sees the one geometry)
  std::vector<double> top_seconds_;
  std::vector<std::shared_ptr<const TriangleAlpha>> alphas_;  // the filters' user data
};

}  // namespace rtsim
