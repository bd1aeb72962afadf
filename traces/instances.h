// Instanced geometry, as game worlds and two-level ray-tracing hardware have it: unique meshes
// (bottom level) placed any number of times by instances (top level), each with its own affine
// transform. An instanced triangle is named by (instance, prim): prim indexes the instance's
// mesh. Memory holds each unique mesh once; flatten() writes the world-space copy that
// single-level consumers and the flattened-versus-instanced checks use.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "traces/ray.h"

namespace rtsim {

// world = linear * object + offset.
struct Transform {
  glm::mat3 linear{1.0f};
  glm::vec3 offset{0.0f};

  glm::vec3 point(const glm::vec3& p) const { return linear * p + offset; }
  glm::vec3 vector(const glm::vec3& v) const { return linear * v; }
};

// The box around an object-space box's eight corners in world space.
Bounds world_box(const Bounds& object, const Transform& to_world);

// The inverse transform (world to object); the caller checks invertibility first.
Transform inverse(const Transform& t);

// An instance is visible to a ray when (mask & the ray type's inclusion mask) != 0.
constexpr uint8_t kAllInstances = 0xFF;

struct Instance {
  uint32_t mesh = 0;  // index into InstancedMesh::meshes
  Transform to_world;
  uint8_t mask = kAllInstances;  // visibility mask (traces/instance_settings.h)
};

struct InstancedMesh {
  std::vector<TriangleMesh> meshes;  // unique geometry, in object space
  std::vector<Instance> instances;

  uint64_t unique_triangles() const;
  uint64_t instanced_triangles() const;  // over every instance
};

// Why instanced geometry cannot be traced (a mesh index out of range, a mesh without
// triangles, a transform that is not finite or not invertible, no instance); empty if fine.
std::string instancing_problem(const InstancedMesh& geometry);

// World-space triangles of every instance, one instance after another: triangle k of instance
// i is at flat_offsets[i] + k.
struct FlatMesh {
  TriangleMesh mesh;
  std::vector<uint64_t> flat_offsets;  // per instance
};
FlatMesh flatten(const InstancedMesh& geometry);
// Just the offsets: where each instance's triangles start in the flattened order.
std::vector<uint64_t> flat_offsets(const InstancedMesh& geometry);

// Fingerprint of instanced geometry: its unique meshes and its instances (mesh, transform).
uint64_t instanced_fingerprint(const InstancedMesh& geometry);

struct InstanceSettings;

// World-space triangles by flat id (flatten()'s order), read from a flat mesh or transformed from
// the instances on demand (bit for bit what flatten() writes), so that consumers of flat ids need
// no flattened copy; with settings that move instances, as they stand in a ray's frame. Refers
// to the mesh, instances and settings it is made from: they must outlive it.
class FlatTriangles {
 public:
  FlatTriangles() = default;                // no triangles
  FlatTriangles(const TriangleMesh& flat);  // NOLINT: a flat mesh is its own flat triangles
  explicit FlatTriangles(const InstancedMesh& geometry, const InstanceSettings* settings = nullptr);

  uint64_t count() const { return count_; }
  // True when the triangles are instances' (world-space corners transformed from object space).
  bool instanced() const { return instances_ != nullptr; }
  // In frame `frame` (a ray's frame: InstanceSettings::pose_frame applies).
  std::array<glm::vec3, 3> corners(uint64_t tri, uint32_t frame = 0) const;
  Bounds bounds() const;  // of every world-space vertex

  // Where a flat triangle is: its instance (0 for a flat mesh) and its triangle in that
  // instance's mesh.
  struct Place {
    uint32_t instance = 0, prim = 0;
  };
  Place locate(uint64_t tri) const;
  // The alpha of the mesh a flat triangle lies in (null if that mesh is opaque), and the
  // triangle's index in it.
  const TriangleAlpha* alpha(uint64_t tri, uint32_t& prim) const;
  // The flat id of triangle prim of an instance's mesh (prim itself for a flat mesh, for kNoHit,
  // kAnyPrim or no instance).
  uint32_t flat_id(uint32_t instance, uint32_t prim) const;
  // A hit that names an instance and a triangle of its mesh (Embree's instances, the two-level
  // model), with prim made the flat id; other hits as they are.
  Hit flat(Hit hit) const {
    hit.prim = flat_id(hit.instance, hit.prim);
    return hit;
  }

 private:
  const TriangleMesh* flat_ = nullptr;
  const InstancedMesh* instances_ = nullptr;
  const InstanceSettings* settings_ = nullptr;
  std::vector<uint32_t> motion_;   // per instance: its motion, or kNoHit; empty if none move
  std::vector<uint64_t> offsets_;  // instances: flat_offsets()
  uint64_t count_ = 0;
};

}  // namespace rtsim
