// Private to workloads/: the built-in scene generators and the small geometry kit they share.
// Everything is built from +, *, / and sqrt only (no sin/cos, no std:: distributions), so a
// built-in scene is bit-identical on every machine and its fingerprint never drifts.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "traces/alpha.h"
#include "workloads/pipeline/rng.h"
#include "workloads/scene.h"

namespace rtsim::builtin {

// Indexed triangles in a local frame, instanced into a scene by SceneBuilder::add.
struct MeshTemplate {
  std::vector<glm::vec3> positions;
  std::vector<std::array<uint32_t, 3>> triangles;
  std::vector<glm::vec2> uvs;  // per position; only alpha-tested templates need them
};

// Unit sphere from an octahedron whose faces are split into level^2 triangles each (8 level^2 in
// all, 4 level^2 + 2 shared vertices), outward winding, watertight.
MeshTemplate octa_sphere(int level);
// Cube [-1,1]^3: 8 vertices, 12 triangles, outward winding.
MeshTemplate unit_cube();
// Quad [-1,1]^2 in the xz plane at y = 0 split into cells x cells squares, facing +y.
MeshTemplate grid_quad(int cells);

// Rotation about +y by the angle whose cosine and sine are c and s (c^2 + s^2 = 1); pass exact
// rationals such as (4/5, 3/5) to stay free of trigonometry.
glm::mat3 rotation_y(float c, float s);

// PCG32 (pipeline/rng.h) on the stream whose increment is O'Neill's reference one
// (pcg-random.org): the same numbers on every platform, unlike the std:: distributions.
class Pcg32 : public pipeline::Pcg32 {
 public:
  explicit Pcg32(uint64_t seed) : pipeline::Pcg32(seed, kReferenceIncrement >> 1) {}
  // Uniform in [-1, 1) with 24 bits, exact in float.
  float symmetric() { return float(int32_t(next() >> 8) - (1 << 23)) * 0x1p-23f; }
  // Three symmetric() draws, z first: the order GCC's right-to-left argument evaluation gave the
  // scenes whose fingerprints are pinned, spelled out so that every compiler agrees.
  glm::vec3 symmetric_vector() {
    float z = symmetric(), y = symmetric(), x = symmetric();
    return {x, y, z};
  }

 private:
  static constexpr uint64_t kReferenceIncrement = 1442695040888963407ull;
};

// Uniform random rotation: a quaternion drawn uniformly in the unit 4-ball, normalized.
glm::mat3 random_rotation(Pcg32& rng);

// A unique mesh of an instanced built-in, made from templates: a material per triangle and the
// object its instances belong to.
struct UniqueMesh {
  TriangleMesh mesh;
  std::vector<uint32_t> materials;
  uint32_t object = 0;

  // Appends the template transformed as p -> offset + rotation * (scale * p), alpha-tested
  // with mask (an index from add_mask, at the template's uvs) unless it is kOpaque.
  void add(const MeshTemplate& t, const glm::vec3& offset, const glm::vec3& scale,
           uint32_t material, const glm::mat3& rotation = glm::mat3(1.0f),
           uint32_t mask = TriangleAlpha::kOpaque);
  // Adds an alpha mask for add(); the first makes the mesh alpha-tested.
  uint32_t add_mask(std::shared_ptr<const AlphaMask> mask);

 private:
  std::shared_ptr<TriangleAlpha> alpha_;  // mesh.alpha, while the mesh is built
};

// The instance transform p -> offset + rotation * (scale * p).
inline Transform placement(const glm::mat3& rotation, const glm::vec3& scale,
                           const glm::vec3& offset) {
  Transform t;
  t.linear = rotation * glm::mat3(glm::vec3(scale.x, 0, 0), glm::vec3(0, scale.y, 0),
                                  glm::vec3(0, 0, scale.z));
  t.offset = offset;
  return t;
}

// Moves the unique meshes into scene.instanced, whose instances place them, with materials per
// mesh triangle and objects per instance (no flattened copy: scene.mesh stays empty).
inline void keep_unique_meshes(std::vector<UniqueMesh> meshes, Scene& scene) {
  for (const Instance& inst : scene.instanced.instances)
    scene.instance_object_ids.push_back(meshes[inst.mesh].object);
  for (UniqueMesh& m : meshes) {
    scene.instanced.meshes.push_back(std::move(m.mesh));
    scene.mesh_material_ids.push_back(std::move(m.materials));
  }
}

// A leaf-shaped alpha mask of size x size texels for a triangle whose texture coordinates are
// kLeafUvs: a leaf from the tip at (0.5, 0) to a stem at the base, `width` its widest point
// across as a fraction of the triangle's width there (about 1), antialiased at the edges; its
// texture at texture_offset (RGBA8: 4 size^2 bytes).
std::shared_ptr<const AlphaMask> leaf_mask(const std::string& name, uint32_t size, float width,
                                           uint64_t texture_offset);
// A leaf triangle's corners (tip, base left, base right) in texture coordinates.
inline const std::array<glm::vec2, 3> kLeafUvs = {glm::vec2(0.5f, 0.0f), glm::vec2(0.0f, 1.0f),
                                                  glm::vec2(1.0f, 1.0f)};
// Adds `leaves` leaf triangles `size` tall, alpha-tested with mask (a leaf_mask), centred
// uniformly in the ellipsoid at centre with radii, each turned at random.
void add_leaves(UniqueMesh& mesh, uint32_t leaves, float size, glm::vec3 centre, glm::vec3 radii,
                uint32_t material, uint32_t mask, Pcg32& rng);

// A dielectric with the given colour and roughness; callers set the other fields.
Material make_material(const std::string& name, const glm::vec3& color, float roughness);

// Appends geometry, materials and object names to a Scene.
class SceneBuilder {
 public:
  explicit SceneBuilder(std::string source);

  uint32_t material(const Material& m);
  uint32_t object(const std::string& name);
  // Appends the template transformed as p -> offset + rotation * (scale * p).
  void add(const MeshTemplate& t, const glm::vec3& offset, const glm::vec3& scale,
           uint32_t material_id, uint32_t object_id, const glm::mat3& rotation = glm::mat3(1.0f));
  // Appends the quad a b c d as triangles (a, b, c) and (a, c, d).
  void quad(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d,
            uint32_t material_id, uint32_t object_id);
  void reserve(size_t vertices, size_t triangles);

  Scene& scene() { return scene_; }

 private:
  Scene scene_;
};

// Parses the N of "grid:N", "foliage:N", "forest:N", "city:N": 1 <= N <= kMaxBuiltinTriangles, else
// InputError naming source.
uint64_t parse_triangle_count(const std::string& source, const std::string& text);
constexpr uint64_t kMaxBuiltinTriangles = 1000000000;

Scene make_cornell();
Scene make_pica();
Scene make_grid(const std::string& source, uint64_t triangles);
Scene make_foliage(const std::string& source, uint64_t triangles);
Scene make_forest(const std::string& source, uint64_t triangles);
Scene make_city(const std::string& source, uint64_t triangles);

// Dispatches "cornell", "pica", "grid:N", "foliage:N", "forest:N", "city:N" ("builtin:" already
// removed); the Scene is not yet finalized.
Scene make_builtin_scene(const std::string& name_and_params);

}  // namespace rtsim::builtin
