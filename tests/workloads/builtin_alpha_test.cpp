// The built-in scenes' foliage is alpha-tested (traces/alpha.h): which triangles, their leaf
// masks and texture layout, and Embree passing a ray through a leaf's hole but not its blade.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "traces/embree_scene.h"
#include "workloads/scene.h"

namespace rtsim {
namespace {

// The fraction of a leaf triangle (texture coordinates (0.5, 0), (0, 1), (1, 1)) that is opaque,
// sampled at texel centres.
double leaf_coverage(const AlphaMask& m) {
  size_t inside = 0, opaque = 0;
  for (uint32_t y = 0; y < m.height; ++y)
    for (uint32_t x = 0; x < m.width; ++x) {
      double u = (x + 0.5) / m.width, v = (y + 0.5) / m.height;
      if (std::abs(u - 0.5) > 0.5 * v) continue;
      ++inside;
      opaque += m.opaque(y * m.width + x);
    }
  return double(opaque) / double(inside);
}

TEST(BuiltinAlpha, PicaHasAHousePlantWithAlphaTestedLeaves) {
  Scene s = load_scene("pica");
  ASSERT_TRUE(s.mesh.alpha);
  const TriangleAlpha& a = *s.mesh.alpha;
  FlatTriangles triangles = s.triangles();
  size_t tested = 0;
  for (uint32_t t = 0; t < s.triangle_count(); ++t) {
    if (!a.tested(t)) continue;
    ++tested;
    EXPECT_EQ(s.object_names[s.attributes(triangles, t).object], "house_plant") << t;
    EXPECT_EQ(a.masks[a.mask_of[t]]->name, "pica_leaf");
  }
  EXPECT_EQ(tested, 160u);
  ASSERT_EQ(a.masks.size(), 1u);
  const AlphaMask& leaf = *a.masks[0];
  EXPECT_EQ(leaf.texture_offset, 0u);
  EXPECT_NEAR(leaf_coverage(leaf), 0.5, 0.1) << "about half a leaf triangle is a hole";
}

TEST(BuiltinAlpha, ForestLeavesAreAlphaTestedWithOneTexturePerTreeVariant) {
  Scene s = load_scene("forest:1000");
  const InstancedMesh& g = s.instanced;
  const uint32_t leaves[3] = {6000, 8000, 10000};
  uint64_t texture_end = 0;
  for (uint32_t m = 0; m < g.meshes.size(); ++m) {
    const TriangleMesh& mesh = g.meshes[m];
    if (m >= 3) {
      EXPECT_FALSE(mesh.alpha) << "rock and terrain are opaque";
      continue;
    }
    ASSERT_TRUE(mesh.alpha);
    size_t tested = 0;
    for (uint32_t t = 0; t < mesh.triangle_count(); ++t) tested += mesh.alpha->tested(t);
    EXPECT_EQ(tested, leaves[m]) << "every leaf, not the trunk";
    ASSERT_EQ(mesh.alpha->masks.size(), 1u);
    const AlphaMask& mask = *mesh.alpha->masks[0];
    EXPECT_GE(mask.texture_offset, texture_end) << "textures do not overlap";
    texture_end = mask.texture_offset + uint64_t(kTexelBytes) * mask.width * mask.height;
    EXPECT_GT(leaf_coverage(mask), 0.35);
    EXPECT_LT(leaf_coverage(mask), 0.65);
  }
}

// A ray along a leaf's normal through its blade hits it; one through the hole beside its stem
// goes on (Embree's intersection filter asks the mask).
TEST(BuiltinAlpha, EmbreeSeesTheLeafBladeButNotItsHole) {
  Scene s = load_scene("forest:1000");
  const TriangleMesh& tree = s.instanced.meshes[0];
  const uint32_t leaf = 12;  // the first triangle after the trunk
  ASSERT_TRUE(tree.alpha->tested(leaf));
  glm::vec3 p[3];
  for (int k = 0; k < 3; ++k) p[k] = tree.positions[tree.triangles[leaf][k]];
  glm::vec3 n = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
  EmbreeScene embree(tree);
  auto shoot = [&](float b1, float b2) {
    Ray ray;
    glm::vec3 at = (1.0f - b1 - b2) * p[0] + b1 * p[1] + b2 * p[2];
    ray.org = at + 0.01f * n;
    ray.dir = -n;
    ray.tmax = 0.02f;
    return embree.trace(ray).prim;
  };
  // Texture coordinates (0.5, 0.45), the blade's widest point, and (0.3, 0.9), beside the stem.
  EXPECT_EQ(shoot(0.225f, 0.225f), leaf);
  EXPECT_EQ(shoot(0.65f, 0.25f), kNoHit);
}

}  // namespace
}  // namespace rtsim
