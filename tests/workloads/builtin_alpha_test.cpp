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

// A short ray along triangle tri's normal through its point at barycentrics (b1, b2).
Ray ray_through(const TriangleMesh& mesh, uint32_t tri, float b1, float b2) {
  glm::vec3 p[3];
  for (int k = 0; k < 3; ++k) p[k] = mesh.positions[mesh.triangles[tri][k]];
  glm::vec3 n = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
  Ray ray;
  ray.org = (1.0f - b1 - b2) * p[0] + b1 * p[1] + b2 * p[2] + 0.01f * n;
  ray.dir = -n;
  ray.tmax = 0.02f;
  return ray;
}

const uint32_t kFirstLeaf = 12;  // of forest's first tree: the first triangle after the trunk
// A leaf's texture coordinates (0.5, 0.45), the blade's widest point, and (0.3, 0.9), beside
// the stem, as barycentrics.
const float kBlade[2] = {0.225f, 0.225f}, kHole[2] = {0.65f, 0.25f};

// A ray along a leaf's normal through its blade hits it; one through the hole beside its stem
// goes on (Embree's intersection filter asks the mask).
TEST(BuiltinAlpha, EmbreeSeesTheLeafBladeButNotItsHole) {
  Scene s = load_scene("forest:1000");
  const TriangleMesh& tree = s.instanced.meshes[0];
  ASSERT_TRUE(tree.alpha->tested(kFirstLeaf));
  EmbreeScene embree(tree);
  auto shoot = [&](const float* b) {
    return embree.trace(ray_through(tree, kFirstLeaf, b[0], b[1])).prim;
  };
  EXPECT_EQ(shoot(kBlade), kFirstLeaf);
  EXPECT_EQ(shoot(kHole), kNoHit);
}

// Embree says whether a query met an alpha-tested candidate, whatever its mask decided: the
// leaf's blade and its hole do, a forced-opaque ray and the opaque trunk (of the same Embree
// geometry, so also through the filter) do not, nor does a ray that meets nothing.
TEST(BuiltinAlpha, EmbreeSaysWhetherAQueryMetAnAlphaTestedCandidate) {
  Scene s = load_scene("forest:1000");
  const TriangleMesh& tree = s.instanced.meshes[0];
  ASSERT_FALSE(tree.alpha->tested(0));
  EmbreeScene embree(tree);
  auto met = [&](Ray ray, bool any_hit, bool force_opaque) {
    ray.force_opaque = force_opaque;
    bool answers[2] = {false, true};  // the query overwrites either
    for (bool& met_alpha : answers)
      if (any_hit)
        embree.occluded(ray, &met_alpha);
      else
        embree.intersect(ray, &met_alpha);
    EXPECT_EQ(answers[0], answers[1]);
    return answers[0];
  };
  Ray blade = ray_through(tree, kFirstLeaf, kBlade[0], kBlade[1]);
  Ray hole = ray_through(tree, kFirstLeaf, kHole[0], kHole[1]);
  Ray trunk = ray_through(tree, 0, 0.3f, 0.3f);
  Ray away = hole;
  away.dir = -hole.dir;
  for (bool any_hit : {false, true}) {
    EXPECT_TRUE(met(blade, any_hit, false)) << any_hit;
    EXPECT_TRUE(met(hole, any_hit, false)) << any_hit;
    EXPECT_FALSE(met(hole, any_hit, true)) << any_hit;
    EXPECT_FALSE(met(trunk, any_hit, false)) << any_hit;
    EXPECT_FALSE(met(away, any_hit, false)) << any_hit;
  }
  EXPECT_EQ(embree.intersect(trunk).prim, 0u) << "the trunk ray does reach the filter";
}

}  // namespace
}  // namespace rtsim
