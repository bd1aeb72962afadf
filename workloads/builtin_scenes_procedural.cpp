// Scalable built-in scenes for BVH and memory studies: "grid:N" (instanced spheres in a regular
// 3D grid, regular and coherent) and "foliage:N" (random small triangles in a box, like leaves:
// incoherent, heavily overlapping bounding boxes). Both have exactly N triangles, are seeded and
// bit-identical on every machine, and fill preallocated arrays (10M triangles in about a second).
#include <algorithm>
#include <cmath>

#include "workloads/builtin_scenes.h"

namespace rtsim::builtin {
namespace {

using V = glm::vec3;

constexpr int kGridSphereLevel = 4;   // 128 triangles, 66 vertices per sphere
constexpr float kGridSpacing = 3.0f;  // sphere radius is 1
constexpr float kFoliageHalfSize = 5.0f;
constexpr uint64_t kFoliageSeed = 0x5eedf011a6e5ull;

// Smallest k with k^3 >= n.
uint64_t cube_root_up(uint64_t n) {
  uint64_t k = 1;
  while (k * k * k < n) ++k;
  return k;
}

}  // namespace

glm::mat3 random_rotation(Pcg32& rng) {
  float w, x, y, z, n2;
  do {
    w = rng.symmetric(), x = rng.symmetric(), y = rng.symmetric(), z = rng.symmetric();
    n2 = w * w + x * x + y * y + z * z;
  } while (n2 > 1.0f || n2 < 1e-4f);
  float s = 2.0f / n2;  // folds the normalization into the matrix
  return glm::mat3(V(1 - s * (y * y + z * z), s * (x * y + w * z), s * (x * z - w * y)),
                   V(s * (x * y - w * z), 1 - s * (x * x + z * z), s * (y * z + w * x)),
                   V(s * (x * z + w * y), s * (y * z - w * x), 1 - s * (x * x + y * y)));
}

Scene make_grid(const std::string& source, uint64_t triangles) {
  const MeshTemplate sphere = octa_sphere(kGridSphereLevel);
  const uint64_t per_copy = sphere.triangles.size();
  const uint64_t copies = (triangles + per_copy - 1) / per_copy;
  const uint64_t side = cube_root_up(copies);

  SceneBuilder b(source);
  Material mirror = make_material("mirror", V(0.95f), 0.0f);
  mirror.metalness = 1.0f;
  Material glass = make_material("glass", V(1.0f), 0.0f);
  glass.transmission = 1.0f;
  const uint32_t materials[4] = {b.material(make_material("rough", V(0.8f), 0.9f)),
                                 b.material(make_material("glossy", V(0.3f, 0.5f, 0.9f), 0.25f)),
                                 b.material(mirror), b.material(glass)};
  b.reserve(copies * sphere.positions.size(), triangles);
  b.scene().object_names.reserve(copies);
  for (uint64_t c = 0; c < copies; ++c) {
    V center(float(c % side), float(c / side % side), float(c / (side * side)));
    uint32_t object = b.object("sphere_" + std::to_string(c));
    uint64_t left = triangles - c * per_copy;
    if (left >= per_copy) {
      b.add(sphere, center * kGridSpacing, V(1.0f), materials[c % 4], object);
      continue;
    }
    // The last copy is cut to exactly N triangles; it keeps only the vertices they use.
    MeshTemplate cut{{}, {sphere.triangles.begin(), sphere.triangles.begin() + left}, {}};
    uint32_t used = 0;
    for (const auto& tri : cut.triangles)
      used = std::max({used, tri[0] + 1, tri[1] + 1, tri[2] + 1});
    cut.positions.assign(sphere.positions.begin(), sphere.positions.begin() + used);
    b.add(cut, center * kGridSpacing, V(1.0f), materials[c % 4], object);
  }
  return std::move(b.scene());
}

Scene make_foliage(const std::string& source, uint64_t triangles) {
  Scene scene;
  scene.source = source;
  Material leaf = make_material("leaf", V(0.3f, 0.6f, 0.15f), 0.6f);
  leaf.translucency = 0.5f;
  scene.materials.push_back(leaf);
  scene.object_names.push_back("leaves");
  scene.material_ids.assign(triangles, 0);
  scene.object_ids.assign(triangles, 0);
  scene.mesh.positions.resize(3 * triangles);
  scene.mesh.triangles.resize(triangles);

  // Leaves shrink as N grows so the box stays about equally full at every N.
  const float size = std::min(1.0f, 1.2f * kFoliageHalfSize / float(cube_root_up(triangles)));
  const V corners[3] = {V(0.0f, size, 0.0f), V(-0.5f * size, -0.4f * size, 0.0f),
                        V(0.5f * size, -0.4f * size, 0.0f)};
  Pcg32 rng(kFoliageSeed);
  V* out = scene.mesh.positions.data();
  for (uint64_t i = 0; i < triangles; ++i) {
    V center = kFoliageHalfSize * rng.symmetric_vector();
    float scale = 1.0f + 0.5f * rng.symmetric();
    glm::mat3 rotation = random_rotation(rng);
    for (int k = 0; k < 3; ++k) *out++ = center + rotation * (scale * corners[k]);
    auto first = uint32_t(3 * i);
    scene.mesh.triangles[i] = {first, first + 1, first + 2};
  }
  return scene;
}

}  // namespace rtsim::builtin
