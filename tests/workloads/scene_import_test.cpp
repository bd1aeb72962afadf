// Round trips through small files written by the test in every supported format: triangle
// counts, positions, object names, and materials mapped from MTL.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>

#include "scene_test_util.h"

namespace rtsim {
namespace {

using test::TempDir;

// Little-endian bytes of a value, for binary PLY and STL.
template <typename T>
std::string bytes(T value) {
  std::string out(sizeof value, '\0');
  std::memcpy(out.data(), &value, sizeof value);
  return out;
}

TEST(SceneImport, ObjWithMtlGivesObjectsAndMaterials) {
  TempDir dir;
  dir.write("two.mtl",
            "newmtl paint\nKd 0.2 0.4 0.6\nNs 98\nNi 1.33\nd 0.25\n"
            "newmtl glow\nKd 1 1 1\nKe 5 4 3\n");
  std::string obj = dir.write("two.obj",
                              "mtllib two.mtl\n"
                              "o panel\nusemtl paint\n"
                              "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                              "f 1 2 3 4\n"
                              "l 1 3\n"
                              "o lamp\nusemtl glow\n"
                              "v 0 0 1\nv 1 0 1\nv 0 1 1\n"
                              "f -3 -2 -1\n"
                              "p 1\n");
  Scene s = load_scene(obj);
  EXPECT_EQ(s.source, obj);
  ASSERT_EQ(s.triangle_count(), 3u) << "quad split in two, line and point dropped";
  EXPECT_EQ(s.mesh.positions.size(), 7u);
  EXPECT_EQ(s.object_names, (std::vector<std::string>{"panel", "lamp"}));
  EXPECT_EQ(s.object_ids, (std::vector<uint32_t>{0, 0, 1}));

  const Material& paint = s.materials[s.material_ids[0]];
  EXPECT_EQ(paint.name, "paint");
  EXPECT_FLOAT_EQ(paint.base_color.y, 0.4f);
  EXPECT_NEAR(paint.roughness, std::pow(2.0f / 100.0f, 0.25f), 1e-6f) << "from Ns 98";
  EXPECT_FLOAT_EQ(paint.transmission, 0.75f) << "from d 0.25";
  EXPECT_FLOAT_EQ(paint.ior, 1.33f);
  EXPECT_EQ(paint.metalness, 0.0f);
  EXPECT_EQ(s.material_ids[1], s.material_ids[0]);
  const Material& glow = s.materials[s.material_ids[2]];
  EXPECT_EQ(glow.name, "glow");
  EXPECT_FLOAT_EQ(glow.emission.x, 5.0f);
  EXPECT_FLOAT_EQ(glow.emission.z, 3.0f);
  EXPECT_EQ(s.bounds.hi, glm::vec3(1.0f));
}

// A flattened scene kept as its instances (for instance masks and motion): every flat triangle,
// material and object as before, the fingerprint of the file it came from.
TEST(SceneImport, AFlattenedSceneKeptAsInstancesKeepsItsFlatIds) {
  std::string path =
      std::string(RTSIM_SOURCE_DIR) + "/../shared/scenes/cornell-box/CornellBox-Original.obj";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " absent (no ../shared here)";
  Scene flat = load_scene(path);
  ASSERT_TRUE(flat.flattened());
  ASSERT_GT(flat.instanced.instances.size(), 1u);
  Scene kept = flat;
  keep_as_instances(kept);
  EXPECT_FALSE(kept.flattened());
  EXPECT_EQ(kept.fingerprint, flat.fingerprint);
  FlatTriangles a = flat.triangles(), b = kept.triangles();
  ASSERT_EQ(b.count(), a.count());
  for (uint64_t t = 0; t < a.count(); ++t) {
    ASSERT_EQ(b.corners(t), a.corners(t)) << "triangle " << t;
    ASSERT_EQ(kept.attributes(b, t).material, flat.attributes(a, t).material);
    ASSERT_EQ(kept.attributes(b, t).object, flat.attributes(a, t).object);
  }
  Scene one_mesh = load_scene("cornell");
  EXPECT_THROW(keep_as_instances(one_mesh), InputError);
}

TEST(SceneImport, ObjPhongSpecularOnlyBecomesMetal) {
  TempDir dir;
  dir.write("m.mtl", "newmtl polished\nKd 0 0 0\nKs 0.7 0.7 0.7\nNs 200\n");
  Scene s = load_scene(dir.write("m.obj",
                                 "mtllib m.mtl\nusemtl polished\n"
                                 "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
  const Material& m = s.materials[s.material_ids[0]];
  EXPECT_EQ(m.metalness, 1.0f);
  EXPECT_FLOAT_EQ(m.base_color.x, 0.7f);
}

TEST(SceneImport, UppercaseExtensionAndMissingMtlStillLoad) {
  TempDir dir;
  Scene s = load_scene(dir.write("A.OBJ",
                                 "mtllib nowhere.mtl\nusemtl x\n"
                                 "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
  EXPECT_EQ(s.triangle_count(), 1u);
}

TEST(SceneImport, AsciiPlyGetsOneDefaultMaterialAndTheFileStemAsObject) {
  TempDir dir;
  std::string ply = dir.write("quad.ply",
                              "ply\nformat ascii 1.0\nelement vertex 5\n"
                              "property float x\nproperty float y\nproperty float z\n"
                              "element face 2\nproperty list uchar int vertex_indices\n"
                              "end_header\n"
                              "0 0 0\n2 0 0\n2 2 0\n0 2 0\n1 1 3\n"
                              "4 0 1 2 3\n3 0 1 4\n");
  Scene s = load_scene(ply);
  EXPECT_EQ(s.triangle_count(), 3u);
  EXPECT_EQ(s.mesh.positions.size(), 5u);
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].name, "default");
  EXPECT_EQ(s.material_ids, (std::vector<uint32_t>{0, 0, 0}));
  EXPECT_EQ(s.object_names, (std::vector<std::string>{"quad"}));
  EXPECT_EQ(s.bounds.lo, glm::vec3(0.0f));
  EXPECT_EQ(s.bounds.hi, glm::vec3(2.0f, 2.0f, 3.0f));
}

TEST(SceneImport, BinaryPlyKeepsExactFloats) {
  TempDir dir;
  std::string data =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
      "property float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  for (float f : {0.1f, 0.2f, 0.3f, 1.1f, 0.2f, 0.3f, 0.1f, 1.2f, -0.3f}) data += bytes(f);
  data += bytes(uint8_t(3)) + bytes(int32_t(0)) + bytes(int32_t(1)) + bytes(int32_t(2));
  Scene s = load_scene(dir.write("tri.ply", data));
  ASSERT_EQ(s.triangle_count(), 1u);
  EXPECT_EQ(s.mesh.vertex(0, 0), glm::vec3(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(s.mesh.vertex(0, 2), glm::vec3(0.1f, 1.2f, -0.3f));
}

TEST(SceneImport, OffTetrahedron) {
  TempDir dir;
  Scene s = load_scene(dir.write("tet.off",
                                 "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                                 "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"));
  EXPECT_EQ(s.triangle_count(), 4u);
  EXPECT_EQ(s.mesh.positions.size(), 4u);
  EXPECT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.object_names, (std::vector<std::string>{"tet"}));
  EXPECT_EQ(s.bounds.hi, glm::vec3(1.0f));
}

TEST(SceneImport, AsciiStlWeldsSharedCorners) {
  TempDir dir;
  auto facet = [](const char* a, const char* b, const char* c) {
    return std::string("facet normal 0 0 1\nouter loop\nvertex ") + a + "\nvertex " + b +
           "\nvertex " + c + "\nendloop\nendfacet\n";
  };
  std::string stl = "solid sq\n" + facet("0 0 0", "1 0 0", "1 1 0") +
                    facet("0 0 0", "1 1 0", "0 1 0") + "endsolid sq\n";
  Scene s = load_scene(dir.write("square.stl", stl));
  EXPECT_EQ(s.triangle_count(), 2u);
  EXPECT_EQ(s.mesh.positions.size(), 4u) << "STL repeats corners per facet; the weld joins them";
  EXPECT_EQ(s.materials.size(), 1u);
}

TEST(SceneImport, BinaryStl) {
  TempDir dir;
  std::string data(80, ' ');  // a binary header must not start with "solid"
  data += bytes(uint32_t(2));
  for (int f = 0; f < 2; ++f) {
    for (float v : {0.0f, 0.0f, 1.0f}) data += bytes(v);  // normal
    for (float v : {0.0f, 0.0f, float(f), 1.0f, 0.0f, float(f), 0.0f, 1.0f, float(f)})
      data += bytes(v);
    data += bytes(uint16_t(0));
  }
  Scene s = load_scene(dir.write("two.stl", data));
  EXPECT_EQ(s.triangle_count(), 2u);
  EXPECT_EQ(s.bounds.hi, glm::vec3(1.0f));
}

}  // namespace
}  // namespace rtsim
