// Alpha-tested triangles (traces/alpha.h): the model's traversal and Embree's intersection
// filter let rays through a mask's holes, for closest-hit and any-hit queries, through many
// masked layers to an opaque one, on one level and on two; flattening keeps the masks.
#include <gtest/gtest.h>

#include <memory>

#include "model/bvh/two_level.h"
#include "model/verify/arbiter.h"
#include "model_test_util.h"
#include "tests/alpha_layers.h"
#include "traces/embree_scene.h"

namespace rtsim {
namespace {

struct Aim {
  glm::vec2 at;
  bool opaque;
};
// Quarter centres: two on the checker's opaque texels, two on its holes.
const Aim kAims[] = {
    {{0.75f, 0.25f}, true}, {{1.75f, 1.25f}, true}, {{1.5f, 0.5f}, false}, {{0.5f, 1.5f}, false}};

TEST(Alpha, RaysPassThroughTheHolesOfEveryLayerToTheOpaqueOne) {
  constexpr int kLayers = 6;
  TriangleMesh mesh = test::layered(kLayers);
  EmbreeScene embree(mesh, 1);
  for (const BvhConfig& config : test::all_configs()) {
    SCOPED_TRACE(describe(config));
    BvhImage image = build_bvh_image(mesh, config);
    TraversalUnit unit(image);
    TraversalState s;
    for (const Aim& aim : kAims) {
      Ray ray = test::ray_to({aim.at, 1.0f}, {aim.at, 0.0f});
      Hit ours = unit.trace(s, ray), reference = embree.intersect(ray);
      float expected_t = aim.opaque ? 1.0f : 1.0f + kLayers;
      EXPECT_EQ(ours.t, expected_t);
      EXPECT_NEAR(reference.t, expected_t, 1e-5f * expected_t);
      EXPECT_EQ(ours.prim, reference.prim);
      EXPECT_EQ(s.counters.trav_alpha_tests, aim.opaque ? 1u : uint64_t(kLayers));
      // Any-hit short of the opaque layer: occluded only on an opaque texel.
      ray.query = Query::AnyHit;
      ray.tmax = kLayers;
      EXPECT_EQ(unit.trace(s, ray).hit(), aim.opaque);
      EXPECT_EQ(embree.occluded(ray), aim.opaque);
    }
  }
}

// A ray forced opaque (DXR's RAY_FLAG_FORCE_OPAQUE) stops at the first masked layer, hole or
// not, with no any-hit call, in the model and in Embree; the arbiter judges it so.
TEST(Alpha, AForcedOpaqueRayStopsAtTheFirstLayerWithoutAnyHitCalls) {
  TriangleMesh mesh = test::layered(3);
  EmbreeScene embree(mesh, 1);
  Arbiter arbiter(mesh, embree);
  BvhImage image = build_bvh_image(mesh, BvhConfig{});
  TraversalUnit unit(image);
  TraversalState s;
  for (const Aim& aim : kAims) {
    Ray ray = test::ray_to({aim.at, 1.0f}, {aim.at, 0.0f});
    ray.force_opaque = true;
    Hit ours = unit.trace(s, ray), reference = embree.intersect(ray);
    EXPECT_EQ(ours.t, 1.0f);
    EXPECT_NEAR(reference.t, 1.0f, 1e-5f);
    EXPECT_EQ(s.counters.trav_alpha_tests, 0u);
    ray.query = Query::AnyHit;
    EXPECT_TRUE(unit.trace(s, ray).hit());
    EXPECT_TRUE(embree.occluded(ray));
  }
  // A model hit in the first layer's hole against a reference behind it: the model is right.
  Ray hole = test::ray_to({1.5f, 0.5f, 1.0f}, {1.5f, 0.5f, 0.0f});
  hole.force_opaque = true;
  Verdict v = arbiter.judge(hole, test::hit_of(6, 4.0f), 0, 1.0f);
  EXPECT_EQ(v.right, RightSide::Model);
}

// The masked mesh placed twice, the second turned half a turn about y: Embree's instances, the
// two-level traversal and the flattened copy agree, and flattening keeps each triangle's mask.
TEST(Alpha, InstancesAndTheFlattenedCopyKeepTheMasks) {
  InstancedMesh g;
  g.meshes.push_back(test::layered(3));
  g.instances.push_back({0, Transform{}});
  Transform turned;
  turned.linear = glm::mat3(glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, -1));
  turned.offset = glm::vec3(2.0f, 0.0f, -10.0f);
  g.instances.push_back({0, turned});
  FlatMesh flat = flatten(g);
  ASSERT_TRUE(flat.mesh.alpha);
  EXPECT_TRUE(flat.mesh.alpha->problem(flat.mesh.triangle_count()).empty());
  EXPECT_EQ(flat.mesh.alpha->masks.size(), 1u) << "the two instances share their mask";
  EmbreeScene instanced(g, 1), flattened(flat.mesh, 1);
  TwoLevelBvh bvh = build_two_level_bvh(g, BvhConfig{});
  TraversalUnit unit(bvh);
  TraversalState s;
  for (const Aim& aim : kAims)
    for (float dz : {1.0f, -1.0f}) {
      // From in front of the first instance, and from behind the second (it faces -z).
      Ray ray = test::ray_to({aim.at, dz > 0 ? 1.0f : -20.0f}, {aim.at, dz > 0 ? 0.0f : -19.0f});
      Hit ours = unit.trace(s, ray), reference = instanced.intersect(ray);
      Hit flat_hit = flattened.intersect(ray);
      ASSERT_TRUE(ours.hit());
      EXPECT_NEAR(ours.t, reference.t, 1e-5f * ours.t);
      EXPECT_NEAR(ours.t, flat_hit.t, 1e-5f * ours.t);
      EXPECT_EQ(ours.instance, reference.instance);
      // From behind, the turned instance puts the holes' aims on its quads' diagonals.
      if (dz > 0) {
        EXPECT_EQ(flat.flat_offsets[ours.instance] + ours.prim, flat_hit.prim);
      }
    }
}

// The arbiter applies the mask: a model hit in a hole is wrong, one on a texel edge is either
// side's, one on an opaque texel is right.
TEST(Alpha, TheArbiterJudgesByTheMask) {
  TriangleMesh mesh = test::layered(1);
  EmbreeScene embree(mesh, 1);
  Arbiter arbiter(mesh, embree);
  auto down = [](float x, float y) { return test::ray_to({x, y, 1.0f}, {x, y, 0.0f}); };
  // x = 1 is the edge between an opaque texel and a hole.
  Verdict edge = arbiter.judge(down(1.0f, 0.5f), test::hit_of(2, 2.0f), 0, 1.0f);
  EXPECT_EQ(edge.cls, MismatchClass::AlphaEdge);
  EXPECT_EQ(edge.right, RightSide::Both);
  Verdict hole = arbiter.judge(down(1.5f, 0.5f), test::hit_of(2, 2.0f), 0, 1.0f);
  EXPECT_EQ(hole.cls, MismatchClass::Unexplained);
  EXPECT_EQ(hole.right, RightSide::Embree);
  Verdict opaque = arbiter.judge(down(0.75f, 0.25f), test::hit_of(2, 2.0f), 0, 1.0f);
  EXPECT_EQ(opaque.right, RightSide::Model);
  EXPECT_TRUE(arbiter.judge(down(1.5f, 0.5f), test::hit_of(2, 2.0f), 2, 2.0f).agree);
}

TEST(Alpha, TheFingerprintSeesTheMask) {
  TriangleMesh a = test::layered(1), b = test::layered(1);
  auto holes = std::make_shared<TriangleAlpha>(*b.alpha);
  auto other = std::make_shared<AlphaMask>(*test::checker());
  other->alpha = {0, 255, 255, 0};
  holes->masks = {other};
  b.alpha = holes;
  TriangleMesh opaque = test::layered(1);
  opaque.alpha = nullptr;
  EXPECT_NE(mesh_fingerprint(a), mesh_fingerprint(b));
  EXPECT_NE(mesh_fingerprint(a), mesh_fingerprint(opaque));
  EXPECT_EQ(mesh_fingerprint(a), mesh_fingerprint(test::layered(1)));
}

TEST(Alpha, CoordinatesWrapAndTheCutoffDecides) {
  AlphaMask m = *test::checker();
  m.alpha = {128, 0, 0, 255};
  EXPECT_TRUE(m.opaque_at({0.25f, 0.25f})) << "128 / 255 >= 0.5";
  EXPECT_TRUE(m.opaque_at({1.25f, -0.75f})) << "repeat";
  EXPECT_FALSE(m.opaque_at({0.75f, 0.25f}));
  m.cutoff = 0.51f;
  EXPECT_FALSE(m.opaque_at({0.25f, 0.25f}));
  EXPECT_TRUE(m.opaque_at({0.75f, 0.75f}));
}

}  // namespace
}  // namespace rtsim
