// Embree 3 (robust mode) over a TriangleMesh: the reference that finds surfaces for the
// pipeline passes (workloads/) and checks every ray of the model (model/verify/).
#pragma once

#include <cstdint>

#include <vector>

#include "traces/instances.h"
#include "traces/ray.h"

struct RTCDeviceTy;
struct RTCSceneTy;

namespace rtsim {

class EmbreeScene {
 public:
  // threads = 0 lets Embree choose; 1 makes the build single-threaded too.
  explicit EmbreeScene(const TriangleMesh& mesh, int threads = 0);
  // Two levels: one Embree scene per unique mesh, placed by instance geometries (Embree's
  // instancing); hits name the instance and the triangle of its mesh. Call
  // instancing_problem() first: this trusts the geometry.
  explicit EmbreeScene(const InstancedMesh& geometry, int threads = 0);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // Closest hit in [tmin, tmax] for a closest-hit query; for an any-hit query, some hit
  // reported as prim = kAnyPrim, t = tmax (Embree does not say which triangle).
  Hit trace(const Ray& ray) const;
  Hit intersect(const Ray& ray) const;  // closest hit regardless of ray.query
  bool occluded(const Ray& ray) const;  // any hit in [tmin, tmax]

 private:
  void open_device(int threads);

  RTCDeviceTy* device_ = nullptr;
  RTCSceneTy* scene_ = nullptr;
  std::vector<RTCSceneTy*> mesh_scenes_;  // instanced: the bottom level
};

}  // namespace rtsim
