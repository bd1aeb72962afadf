// The built-in scenes: exact triangle counts, named objects and materials, bounds, and
// fingerprints that are stable across runs and machines.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>

#include <glm/geometric.hpp>

#include "workloads/scene.h"

namespace rtsim {
namespace {

uint32_t object_id(const Scene& s, const std::string& name) {
  auto it = std::find(s.object_names.begin(), s.object_names.end(), name);
  EXPECT_NE(it, s.object_names.end()) << "no object named " << name;
  return uint32_t(it - s.object_names.begin());
}

size_t triangles_of(const Scene& s, uint32_t object) {
  FlatTriangles triangles = s.triangles();
  size_t n = 0;
  for (uint64_t t = 0; t < s.triangle_count(); ++t)
    n += s.attributes(triangles, t).object == object;
  return n;
}

void expect_vec3_eq(const glm::vec3& a, const glm::vec3& b, const char* what) {
  EXPECT_FLOAT_EQ(a.x, b.x) << what;
  EXPECT_FLOAT_EQ(a.y, b.y) << what;
  EXPECT_FLOAT_EQ(a.z, b.z) << what;
}

TEST(BuiltinScenes, NamesAreRecognizedWithOrWithoutPrefix) {
  for (const char* spec :
       {"cornell", "builtin:cornell", "pica", "grid:10", "builtin:foliage:3", "forest:9", "city:9"})
    EXPECT_TRUE(is_builtin_scene(spec)) << spec;
  for (const char* spec : {"cornell.obj", "scenes/pica.gltf", "/tmp/grid.ply"})
    EXPECT_FALSE(is_builtin_scene(spec)) << spec;
  EXPECT_EQ(builtin_scene_names(),
            (std::vector<std::string>{"cornell", "pica", "grid:N", "foliage:N", "forest:N",
                                      "city:N", "hardcases"}));
  EXPECT_EQ(load_scene("cornell").fingerprint, load_scene("builtin:cornell").fingerprint);
}

TEST(BuiltinScenes, CornellBoxIsTheMeasuredBox) {
  Scene s = load_scene("cornell");
  EXPECT_EQ(s.source, "builtin:cornell");
  EXPECT_EQ(s.triangle_count(), 32u);
  EXPECT_EQ(s.object_names,
            (std::vector<std::string>{"floor", "ceiling", "back_wall", "right_wall", "left_wall",
                                      "short_block", "tall_block", "light"}));
  EXPECT_EQ(triangles_of(s, object_id(s, "tall_block")), 10u);
  EXPECT_EQ(triangles_of(s, object_id(s, "light")), 2u);
  expect_vec3_eq(s.bounds.lo, glm::vec3(0.0f), "bounds.lo");
  expect_vec3_eq(s.bounds.hi, glm::vec3(556.0f, 548.8f, 559.2f), "bounds.hi");
  // Every light triangle is emissive, nothing else is; the red wall is at +x, green at x = 0.
  for (size_t t = 0; t < s.triangle_count(); ++t) {
    const Material& m = s.materials[s.material_ids[t]];
    bool is_light = s.object_names[s.object_ids[t]] == "light";
    EXPECT_EQ(m.emission.x > 0.0f, is_light) << "triangle " << t;
    if (is_light) expect_vec3_eq(m.emission, glm::vec3(17.0f, 12.0f, 4.0f), "light emission");
    if (s.object_names[s.object_ids[t]] == "left_wall") {
      EXPECT_EQ(m.name, "red");
    }
    if (s.object_names[s.object_ids[t]] == "right_wall") {
      EXPECT_EQ(m.name, "green");
    }
  }
}

TEST(BuiltinScenes, PicaHasEveryMaterialFamilyAndOneLight) {
  Scene s = load_scene("pica");
  EXPECT_EQ(s.source, "builtin:pica");
  EXPECT_EQ(s.triangle_count(), 4328u);
  expect_vec3_eq(s.bounds.lo, glm::vec3(-6.0f, 0.0f, -6.0f), "bounds.lo");
  expect_vec3_eq(s.bounds.hi, glm::vec3(6.0f, 4.0f, 6.0f), "bounds.hi");
  EXPECT_EQ(triangles_of(s, object_id(s, "light")), 128u);
  EXPECT_EQ(triangles_of(s, object_id(s, "floor")), 512u);
  for (uint32_t o = 0; o < s.object_names.size(); ++o)
    EXPECT_GT(triangles_of(s, o), 0u) << s.object_names[o];

  std::set<std::string> families;
  for (const Material& m : s.materials) {
    if (m.emission.x > 0.0f) families.insert("emissive");
    if (m.metalness == 1.0f && m.roughness == 0.0f) families.insert("mirror");
    if (m.transmission == 1.0f && m.ior == 1.5f) families.insert("glass");
    if (m.translucency > 0.0f) families.insert("translucent");
    if (m.layers == 2) families.insert("layered");
    if (m.metalness == 0.0f && m.roughness > 0.0f && m.roughness <= 0.3f) families.insert("glossy");
    if (m.roughness >= 0.8f) families.insert("rough");
  }
  EXPECT_EQ(families, (std::set<std::string>{"emissive", "mirror", "glass", "translucent",
                                             "layered", "glossy", "rough"}));
  size_t emissive_triangles = 0;
  for (size_t t = 0; t < s.triangle_count(); ++t)
    emissive_triangles += s.materials[s.material_ids[t]].emission.x > 0.0f;
  EXPECT_EQ(emissive_triangles, 128u) << "only the light emits";
}

// pica is made as SEED's world is, from instances (one sphere mesh placed six times with six
// materials, one wall mesh three times), and keeps its flattened copy: exactly what its
// instances make, every triangle keeping its material and object when the scene is kept as
// instances for masks and motion.
TEST(BuiltinScenes, PicaIsInstancesWithAFlattenedCopy) {
  Scene s = load_scene("pica");
  ASSERT_TRUE(s.flattened());
  const InstancedMesh& g = s.instanced;
  EXPECT_EQ(g.meshes.size(), 8u);
  EXPECT_EQ(g.instances.size(), 17u);
  EXPECT_EQ(g.unique_triangles(), 512u + 128u + 512u + 128u + 3 * 12u + (12u + 160u));
  EXPECT_EQ(g.instanced_triangles(), s.triangle_count());
  std::vector<uint32_t> placed(g.meshes.size(), 0);
  for (const Instance& inst : g.instances) ++placed[inst.mesh];
  EXPECT_EQ(*std::max_element(placed.begin(), placed.end()), 6u) << "the sphere";
  TriangleMesh copy = flatten(g).mesh;
  ASSERT_EQ(copy.positions.size(), s.mesh.positions.size());
  EXPECT_EQ(std::memcmp(copy.positions.data(), s.mesh.positions.data(),
                        copy.positions.size() * sizeof(glm::vec3)),
            0)
      << "bit for bit";
  EXPECT_EQ(copy.triangles, s.mesh.triangles);

  Scene kept = s;
  keep_as_instances(kept);
  ASSERT_FALSE(kept.flattened());
  FlatTriangles a = s.triangles(), b = kept.triangles();
  std::set<uint32_t> sphere_materials;
  for (uint64_t t = 0; t < s.triangle_count(); ++t) {
    ASSERT_EQ(b.corners(t), a.corners(t)) << "triangle " << t;
    TriangleAttributes before = s.attributes(a, t), after = kept.attributes(b, t);
    ASSERT_EQ(after.material, before.material) << "triangle " << t;
    ASSERT_EQ(after.object, before.object) << "triangle " << t;
    if (g.instances[b.locate(t).instance].mesh == g.instances[4].mesh)
      sphere_materials.insert(after.material);
  }
  EXPECT_EQ(sphere_materials.size(), 6u);
}

TEST(BuiltinScenes, GridHasExactlyNTriangles) {
  for (uint64_t n : {1u, 127u, 128u, 129u, 1000u, 100000u}) {
    Scene s = load_scene("grid:" + std::to_string(n));
    EXPECT_EQ(s.triangle_count(), n);
    EXPECT_EQ(s.source, "builtin:grid:" + std::to_string(n));
    EXPECT_EQ(s.object_names.size(), (n + 127) / 128) << "one sphere per 128 triangles";
  }
  Scene s = load_scene("grid:1000");  // 8 spheres of radius 1, 2 x 2 x 2, 3 apart
  expect_vec3_eq(s.bounds.lo, glm::vec3(-1.0f), "bounds.lo");
  expect_vec3_eq(s.bounds.hi, glm::vec3(4.0f), "bounds.hi");
  EXPECT_EQ(load_scene("builtin:grid:007").source, "builtin:grid:7");
}

TEST(BuiltinScenes, FoliageHasExactlyNTrianglesInsideTheBox) {
  for (uint64_t n : {1u, 2u, 999u, 100000u}) {
    Scene s = load_scene("foliage:" + std::to_string(n));
    EXPECT_EQ(s.triangle_count(), n);
    EXPECT_EQ(s.mesh.positions.size(), 3 * n);
    EXPECT_EQ(s.source, "builtin:foliage:" + std::to_string(n));
    // Leaf centres fill [-5, 5]^3; a leaf reaches at most 1.5 leaf sizes past its centre.
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_GE(s.bounds.lo[axis], -6.5f);
      EXPECT_LE(s.bounds.hi[axis], 6.5f);
      if (n >= 1000) {
        EXPECT_LT(s.bounds.lo[axis], -4.9f) << "leaves should fill the box";
      }
    }
  }
}

// Each leaf is the same triangle, scaled and rotated: edge ratios survive, orientations vary.
TEST(BuiltinScenes, FoliageLeavesAreRigidlyRotatedCopies) {
  Scene s = load_scene("foliage:1000");
  float min_nz = 1.0f, max_nz = -1.0f;
  for (size_t t = 0; t < s.triangle_count(); ++t) {
    glm::vec3 a = s.mesh.vertex(t, 0), b = s.mesh.vertex(t, 1), c = s.mesh.vertex(t, 2);
    // Template: apex (0, 1) over a base from (-0.5, -0.4) to (0.5, -0.4).
    EXPECT_NEAR(glm::length(a - b) / glm::length(b - c), std::sqrt(0.25f + 1.96f), 1e-4f);
    EXPECT_NEAR(glm::length(a - b), glm::length(a - c), 1e-4f * glm::length(a - b));
    glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
    min_nz = std::min(min_nz, n.z), max_nz = std::max(max_nz, n.z);
  }
  EXPECT_LT(min_nz, -0.99f);
  EXPECT_GT(max_nz, 0.99f);
}

// A scene kept as instances: no flattened copy, materials per unique mesh and objects per
// instance that flat_mesh() turns into the flattened mesh's, triangle for triangle.
void expect_kept_as_instances(const Scene& s) {
  const InstancedMesh& g = s.instanced;
  EXPECT_FALSE(s.flattened());
  EXPECT_TRUE(s.mesh.positions.empty() && s.material_ids.empty() && s.object_ids.empty());
  ASSERT_EQ(s.mesh_material_ids.size(), g.meshes.size());
  EXPECT_EQ(s.instance_object_ids.size(), g.instances.size());
  EXPECT_EQ(instanced_fingerprint(g), s.fingerprint);
  Scene copy = s;
  EXPECT_EQ(flat_mesh(copy).positions, flatten(g).mesh.positions);
  ASSERT_EQ(copy.material_ids.size(), s.triangle_count());
  FlatTriangles triangles = s.triangles();
  for (uint64_t t = 0; t < s.triangle_count(); t += 997) {
    TriangleAttributes a = s.attributes(triangles, t);
    EXPECT_EQ(a.material, copy.material_ids[t]);
    EXPECT_EQ(a.object, copy.object_ids[t]);
  }
}

// A forest of instances: the unique meshes held once and no flattened copy, placed until N
// instanced triangles; flat_mesh() makes exactly what the instances make.
TEST(BuiltinScenes, ForestIsInstancesOfAFewUniqueMeshes) {
  for (uint64_t n : {1u, 100000u, 2000000u}) {
    Scene s = load_scene("forest:" + std::to_string(n));
    const InstancedMesh& g = s.instanced;
    ASSERT_EQ(g.meshes.size(), 5u) << "three trees, a rock, the terrain";
    EXPECT_EQ(instancing_problem(g), "");
    EXPECT_GE(g.instanced_triangles(), n);
    EXPECT_LT(g.instanced_triangles(), std::max<uint64_t>(n, 8192) + 10012 + 288)
        << "at most one tree (and its rock) past N";
    EXPECT_EQ(s.triangle_count(), g.instanced_triangles());
    EXPECT_EQ(g.unique_triangles(), 3 * 12 + 6000 + 8000 + 10000 + 288 + 8192);
    expect_kept_as_instances(s);
    EXPECT_EQ(s.mesh_material_ids[4].size(), 8192u) << "materials per unique triangle";
  }
  Scene s = load_scene("forest:1000000");
  size_t trees = 0, rocks = 0;
  for (const Instance& inst : s.instanced.instances) {
    trees += inst.mesh < 3;
    rocks += inst.mesh == 3;
  }
  EXPECT_EQ(rocks, (trees + 3) / 4) << "a rock beside every fourth tree";
  EXPECT_EQ(triangles_of(s, object_id(s, "terrain")), 8192u);
  EXPECT_EQ(load_scene("forest:1000000").fingerprint, s.fingerprint) << "seeded";
}

// A city of instances: buildings, props and street tiles held once and no flattened copy, whole
// blocks placed until N instanced triangles; flat_mesh() makes exactly what the instances make.
TEST(BuiltinScenes, CityIsInstancesOfAFewUniqueMeshes) {
  // A street tile, four of the largest building, 8 lamps, 4 trees, 4 benches and 8 cars.
  const uint64_t largest_block = 548 + 4 * 5652 + 8 * 108 + 4 * 212 + 4 * 48 + 8 * 324;
  for (uint64_t n : {1u, 100000u, 2000000u}) {
    Scene s = load_scene("city:" + std::to_string(n));
    const InstancedMesh& g = s.instanced;
    ASSERT_EQ(g.meshes.size(), 11u) << "a lamp, a car, a bench, a tree, a street tile, 6 buildings";
    EXPECT_EQ(instancing_problem(g), "");
    EXPECT_GE(g.instanced_triangles(), n);
    EXPECT_LE(g.instanced_triangles(), n - 1 + largest_block) << "at most one block past N";
    EXPECT_EQ(s.triangle_count(), g.instanced_triangles());
    EXPECT_EQ(g.unique_triangles(), 108 + 324 + 48 + 212 + 548 + 20016);
    expect_kept_as_instances(s);
    EXPECT_EQ(s.mesh_material_ids[4].size(), 548u) << "materials per unique triangle";
  }
  Scene s = load_scene("city:1000000");
  EXPECT_EQ(s.object_names,
            (std::vector<std::string>{"buildings", "lamps", "cars", "benches", "trees", "ground"}));
  ASSERT_EQ(s.cameras.size(), 1u) << "a view into the city, however wide it is";
  std::vector<size_t> placements(s.instanced.meshes.size());
  for (const Instance& inst : s.instanced.instances) {
    ++placements[inst.mesh];
    // Turned by quarter turns about +y: exact, no trigonometry.
    const glm::mat3& m = inst.to_world.linear;
    EXPECT_TRUE(m[0].y == 0 && m[2].y == 0 && m[1].x == 0 && m[1].z == 0);
    EXPECT_TRUE((m[0].x == 0 && m[2].z == 0) || (m[0].z == 0 && m[2].x == 0));
  }
  EXPECT_GT(*std::max_element(placements.begin(), placements.end()), 100u)
      << "a mesh placed many times";
  for (size_t building = 5; building < 11; ++building)
    EXPECT_GT(s.instanced.meshes[building].triangle_count(), 900u) << "facades of inset windows";
  EXPECT_EQ(triangles_of(s, object_id(s, "ground")), 548 * placements[4]) << "a tile a block";
  bool glossy_glass = false;
  for (const Material& m : s.materials)
    glossy_glass |= m.name == "window_glass" && m.roughness <= 0.1f;
  EXPECT_TRUE(glossy_glass) << "windows give the reflection pass work";
  EXPECT_EQ(load_scene("city:1000000").fingerprint, s.fingerprint) << "seeded";
}

TEST(BuiltinScenes, FingerprintsAreStableAndTellScenesApart) {
  for (const char* spec :
       {"cornell", "pica", "grid:5000", "foliage:5000", "forest:50000", "city:50000"})
    EXPECT_EQ(load_scene(spec).fingerprint, load_scene(spec).fingerprint) << spec;
  std::set<uint64_t> distinct;
  for (const char* spec : {"cornell", "pica", "grid:1000", "grid:1001", "grid:2000", "foliage:1000",
                           "foliage:1001", "foliage:2000", "city:1000", "city:50000"})
    distinct.insert(load_scene(spec).fingerprint);
  EXPECT_EQ(distinct.size(), 10u);
}

// Built-ins use no trigonometry and their own RNG, so these values hold on every machine. If a
// scene is changed on purpose, update its value here and say so in the commit.
TEST(BuiltinScenes, FingerprintsMatchTheRecordedValues) {
  EXPECT_EQ(load_scene("cornell").fingerprint, 0xdeccccc0edbf3e9aull);
  EXPECT_EQ(load_scene("pica").fingerprint, 0xc1c3f8f27d98c1e5ull);
  EXPECT_EQ(load_scene("grid:1000").fingerprint, 0x45a8d68f7e3599a7ull);
  EXPECT_EQ(load_scene("foliage:1000").fingerprint, 0x05253d99433d5864ull);
  EXPECT_EQ(load_scene("forest:1000000").fingerprint, 0x76c070cbfd040f13ull)
      << "its unique meshes and instances (instanced_fingerprint)";
  EXPECT_EQ(load_scene("city:1000000").fingerprint, 0x7bacd6216199162dull)
      << "its unique meshes and instances (instanced_fingerprint)";
}

TEST(BuiltinScenes, TenMillionTriangles) {
  for (const char* spec : {"grid:10000000", "foliage:10000000"}) {
    Scene s = load_scene(spec);
    EXPECT_EQ(s.triangle_count(), 10000000u) << spec;
    EXPECT_EQ(s.material_ids.size(), 10000000u) << spec;
    EXPECT_LE(s.mesh.positions.capacity(), 30000000u) << spec << ": no over-allocation";
  }
}

}  // namespace
}  // namespace rtsim
