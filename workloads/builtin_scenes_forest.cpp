// "forest:N": a forest built as games build worlds, from instances. Unique meshes: three tree
// variants (a trunk and a crown of separate small alpha-tested leaf triangles, each variant's
// leaf texture 64 KiB, one after another), a rock and a terrain mound;
// instances place them with their own rotation about +y and scale (the terrain non-uniformly).
// N is the instanced triangles asked for: trees (with a rock beside every fourth) are added on
// a jittered grid until N is reached. The scene keeps only its unique geometry and instances
// (Scene::instanced, no flattened copy: bvh.instancing = "auto" builds two levels over it, and
// the workload passes trace Embree's instances). Seeded, bit-identical on every machine (+, *,
// / and sqrt only).
#include <cmath>
#include <memory>
#include <string>

#include "workloads/builtin_scenes.h"

namespace rtsim::builtin {
namespace {

using V = glm::vec3;

constexpr uint64_t kForestSeed = 0xf0e57ull;
constexpr uint32_t kLeaves[3] = {6000, 8000, 10000};  // leaf triangles of each tree variant
constexpr float kLeafWidths[3] = {1.0f, 0.8f, 1.1f};  // each variant's leaf_mask width
constexpr uint32_t kLeafTexels = 128;                 // a side of each variant's leaf texture
constexpr float kTreeSpacing = 8.0f;
constexpr int kRockLevel = 6;      // octa_sphere: 288 triangles
constexpr int kTerrainCells = 64;  // grid_quad: 8192 triangles
constexpr float kTerrainHeight = 6.0f;

enum Kind : uint32_t { kTrees, kRocks, kTerrain };

// A trunk and a crown: leaf triangles centred uniformly in an ellipsoid above the trunk, each
// alpha-tested with the variant's leaf mask (about half of a leaf triangle is a hole).
UniqueMesh make_tree(uint32_t leaves, float width, Pcg32& rng, uint32_t bark, uint32_t leaf,
                     std::shared_ptr<const AlphaMask> leaf_shape) {
  UniqueMesh tree;
  tree.add(unit_cube(), V(0, 2.0f, 0), V(0.25f, 2.0f, 0.25f), bark);
  const uint32_t mask = tree.add_mask(std::move(leaf_shape));
  add_leaves(tree, leaves, 0.35f, V(0, 5.5f, 0), V(width, 2.5f, width), leaf, mask, rng);
  return tree;
}

// The mound's height at (x, z) in [-1, 1]^2, before the instance's scale.
float mound(float x, float z) {
  return (1 - x * x) * (1 - z * z);
}

UniqueMesh make_terrain(uint32_t ground) {
  UniqueMesh terrain;
  terrain.object = kTerrain;
  MeshTemplate quad = grid_quad(kTerrainCells);
  for (V& p : quad.positions) p.y = mound(p.x, p.z);
  terrain.add(quad, V(0), V(1.0f), ground);
  return terrain;
}

// A rotation about +y by a random angle (its cosine and sine from a random direction).
glm::mat3 random_yaw(Pcg32& rng) {
  float c, s, n2;
  do c = rng.symmetric(), s = rng.symmetric(), n2 = c * c + s * s;
  while (n2 > 1.0f || n2 < 1e-4f);
  float n = std::sqrt(n2);
  return rotation_y(c / n, s / n);
}

}  // namespace

Scene make_forest(const std::string& source, uint64_t triangles) {
  Scene scene;
  scene.source = source;
  Material leaf = make_material("leaf", V(0.3f, 0.6f, 0.15f), 0.6f);
  leaf.translucency = 0.5f;
  scene.materials = {leaf, make_material("bark", V(0.35f, 0.25f, 0.15f), 0.8f),
                     make_material("rock", V(0.5f, 0.5f, 0.48f), 0.7f),
                     make_material("ground", V(0.3f, 0.35f, 0.2f), 0.9f)};
  scene.object_names = {"trees", "rocks", "terrain"};
  Pcg32 rng(kForestSeed);
  std::vector<UniqueMesh> parts;
  for (uint32_t v = 0; v < 3; ++v) {
    auto shape = leaf_mask("leaf_" + std::to_string(v), kLeafTexels, kLeafWidths[v],
                           v * kTexelBytes * kLeafTexels * kLeafTexels);
    parts.push_back(make_tree(kLeaves[v], 1.6f + 0.3f * float(v), rng, 1, 0, std::move(shape)));
  }
  UniqueMesh rock;
  rock.object = kRocks;
  rock.add(octa_sphere(kRockLevel), V(0), V(1.2f, 0.7f, 1.0f), 2);
  parts.push_back(std::move(rock));
  parts.push_back(make_terrain(3));
  const uint32_t rock_mesh = 3, terrain_mesh = 4;

  // Trees (and rocks) until N instanced triangles, the terrain's included; at least one.
  uint64_t trees = 0, placed = parts[terrain_mesh].mesh.triangle_count();
  while (trees == 0 || placed < triangles) {
    placed += parts[trees % 3].mesh.triangle_count();
    if (trees % 4 == 0) placed += parts[rock_mesh].mesh.triangle_count();
    ++trees;
  }
  auto side = uint64_t(std::ceil(std::sqrt(double(trees))));
  const float half = 0.5f * kTreeSpacing * float(side);
  InstancedMesh& g = scene.instanced;
  g.instances.push_back(
      {terrain_mesh, placement(glm::mat3(1.0f), V(half, kTerrainHeight, half), V(0))});
  auto ground = [&](float x, float z) { return kTerrainHeight * mound(x / half, z / half); };
  for (uint64_t i = 0; i < trees; ++i) {
    float x = (float(i % side) + 0.5f + 0.3f * rng.symmetric()) * kTreeSpacing - half;
    float z = (float(i / side) + 0.5f + 0.3f * rng.symmetric()) * kTreeSpacing - half;
    float scale = 1.0f + 0.2f * rng.symmetric();
    g.instances.push_back(
        {uint32_t(i % 3), placement(random_yaw(rng), V(scale), V(x, ground(x, z), z))});
    if (i % 4 != 0) continue;
    float rx = x + 0.5f * kTreeSpacing, rz = z + 0.25f * kTreeSpacing;
    float rock_scale = 1.0f + 0.5f * rng.symmetric();
    g.instances.push_back({rock_mesh, placement(random_yaw(rng), V(rock_scale),
                                                V(rx, ground(rx, rz) - 0.2f * rock_scale, rz))});
  }
  keep_unique_meshes(std::move(parts), scene);
  return scene;
}

}  // namespace rtsim::builtin
