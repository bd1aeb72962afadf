// Traversal unit: counters, access lists, step sequence, ordering, any-hit, +-0 slabs.
#include <gtest/gtest.h>

#include <limits>

#include "model_test_util.h"
#include "traces/embree_scene.h"

namespace rtsim {
namespace {

// Two unit triangles facing +z at z = 0 (x in [0, 1]) and z = -5 (x in [10, 11]).
TriangleMesh two_apart() {
  TriangleMesh mesh;
  test::add_triangle(mesh, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  test::add_triangle(mesh, {10, 0, -5}, {11, 0, -5}, {10, 1, -5});
  return mesh;
}

TEST(Traversal, CountersAndAccessesOfOneHit) {
  TriangleMesh mesh = two_apart();
  BvhImage image = build_bvh_image(mesh, test::config(NodeFormat::Aabb32, 2, 1));
  TraversalUnit unit(image);
  TraversalState s;
  Hit hit = unit.trace(s, test::ray_to({0.2f, 0.2f, 1.0f}, {0.2f, 0.2f, 0.0f}));
  ASSERT_EQ(hit.prim, 0u);
  EXPECT_EQ(hit.t, 1.0f);
  EXPECT_EQ(s.counters.trav_nodes, 1u);
  EXPECT_EQ(s.counters.trav_leaves, 1u);
  EXPECT_EQ(s.counters.trav_prims, 1u);
  EXPECT_EQ(s.counters.trav_prim_hits, 1u);
  ASSERT_EQ(s.accesses.size(), 2u);
  EXPECT_EQ(s.accesses[0].address, image.node_address(0));
  EXPECT_EQ(s.accesses[0].bytes, 64u);
  EXPECT_EQ(s.accesses[0].kind, AccessKind::Node);
  EXPECT_EQ(s.accesses[1].bytes, 40u);
  EXPECT_EQ(s.accesses[1].kind, AccessKind::Triangle);
  EXPECT_GE(s.accesses[1].address, image.triangle_base);
}

TEST(Traversal, MissFetchesOnlyTheRoot) {
  BvhImage image = build_bvh_image(two_apart(), test::config(NodeFormat::Cwbvh8, 8, 1));
  TraversalUnit unit(image);
  TraversalState s;
  Hit hit = unit.trace(s, test::ray_to({5, 5, 5}, {5, 6, 5}));
  EXPECT_FALSE(hit.hit());
  EXPECT_EQ(s.counters.trav_nodes, 1u);
  EXPECT_EQ(s.counters.trav_leaves, 0u);
  ASSERT_EQ(s.accesses.size(), 1u);
  EXPECT_EQ(s.accesses[0].bytes, 80u);
}

TEST(Traversal, StepsReportEachVisitThenDone) {
  BvhImage image = build_bvh_image(two_apart(), test::config(NodeFormat::Aabb32, 2, 1));
  TraversalUnit unit(image);
  TraversalState s;
  unit.begin(s, test::ray_to({0.2f, 0.2f, 1.0f}, {0.2f, 0.2f, 0.0f}));
  StepResult first = unit.step(s);
  EXPECT_EQ(first.kind, StepKind::Node);
  EXPECT_EQ(first.tests, 2u);
  EXPECT_EQ(first.hits, 1u);
  EXPECT_EQ(first.access_count, 1u);
  StepResult second = unit.step(s);
  EXPECT_EQ(second.kind, StepKind::Leaf);
  EXPECT_EQ(second.first_access, 1u);
  EXPECT_EQ(second.hits, 1u);
  EXPECT_EQ(unit.step(s).kind, StepKind::Done);
  EXPECT_TRUE(s.done);
  EXPECT_EQ(unit.result(s, test::ray_to({0.2f, 0.2f, 1.0f}, {0.2f, 0.2f, 0.0f})).prim, 0u);
}

// A stack of parallel triangles along the ray: near-first order finds the nearest leaf first
// and culls the others without fetching them.
TEST(Traversal, NearChildFirstCullsFartherLeaves) {
  TriangleMesh mesh;
  for (int i = 0; i < 8; ++i) {
    float z = float(i * 3);
    test::add_triangle(mesh, {0, 0, z}, {1, 0, z}, {0, 1, z});
  }
  for (const BvhConfig& c : test::all_configs()) {
    BvhConfig one = c;
    one.max_leaf_size = 1;
    BvhImage image = build_bvh_image(mesh, one);
    TraversalUnit unit(image);
    TraversalState s;
    for (float from : {-1.0f, 30.0f}) {
      Ray ray = test::ray_to({0.2f, 0.2f, from}, {0.2f, 0.2f, 10.0f});
      Hit hit = unit.trace(s, ray);
      EXPECT_EQ(hit.prim, from < 0 ? 0u : 7u) << describe(one);
      EXPECT_EQ(s.counters.trav_leaves, 1u) << describe(one);
    }
  }
}

TEST(Traversal, AnyHitStopsAtTheFirstHit) {
  TriangleMesh mesh;
  for (int i = 0; i < 30; ++i) test::add_triangle(mesh, {0, 0, 5}, {1, 0, 5}, {0, 1, 5});
  BvhImage image = build_bvh_image(mesh, BvhConfig{});
  TraversalUnit unit(image);
  TraversalState s;
  Ray ray = test::ray_to({0.2f, 0.2f, -1.0f}, {0.2f, 0.2f, 40.0f});
  ray.query = Query::AnyHit;
  ray.tmax = 100.0f;
  Hit hit = unit.trace(s, ray);
  EXPECT_EQ(hit.prim, kAnyPrim);
  EXPECT_EQ(hit.t, 100.0f);
  EXPECT_EQ(s.counters.trav_prim_hits, 1u);
  EXPECT_TRUE(s.stack.empty());
  EXPECT_EQ(s.counters.trav_prims, 1u);
  // Closest-hit must test all 30 copies: each might be nearer by a rounding.
  ray.query = Query::ClosestHit;
  unit.trace(s, ray);
  EXPECT_EQ(s.counters.trav_prims, 30u);
}

// Origins exactly on box planes with +0 / -0 direction components: 0 * inf gives NaN in the
// slab test, which must count as inside.
TEST(Traversal, SignedZeroDirectionsOnSlabPlanes) {
  TriangleMesh mesh;
  test::add_triangle(mesh, {-1, -1, 5}, {0, -1, 5}, {0, 1, 5});
  test::add_triangle(mesh, {0, -1, 5}, {1, 1, 5}, {0, 1, 5});
  for (const BvhConfig& c : test::all_configs()) {
    BvhConfig one = c;
    one.max_leaf_size = 1;
    BvhImage image = build_bvh_image(mesh, one);
    TraversalUnit unit(image);
    TraversalState s;
    for (float zx : {0.0f, -0.0f})
      for (float zy : {0.0f, -0.0f})
        for (float x : {0.0f, -1.0f, 1.0f}) {
          Ray ray;
          ray.org = {x, x, 0.0f};  // the shared edge at x = 0, the corners at +-1
          ray.dir = {zx, zy, 1.0f};
          EXPECT_TRUE(unit.trace(s, ray).hit()) << describe(one) << " x=" << x;
        }
  }
}

TEST(Traversal, IdenticalRunsGiveIdenticalAccesses) {
  TriangleMesh mesh = test::random_soup(2000, 0.4f, 21);
  BvhImage image = build_bvh_image(mesh, BvhConfig{});
  TraversalUnit unit(image);
  TraversalState a, b;
  for (const Ray& ray : sample_random_rays(mesh, 200, 3)) {
    unit.trace(a, ray);
    unit.trace(b, ray);
    ASSERT_EQ(a.accesses.size(), b.accesses.size());
    for (size_t i = 0; i < a.accesses.size(); ++i)
      ASSERT_EQ(a.accesses[i].address, b.accesses[i].address);
    EXPECT_EQ(a.counters.trav_nodes, b.counters.trav_nodes);
  }
}

TEST(Traversal, AccessListMatchesCounters) {
  TriangleMesh mesh = test::random_soup(2000, 0.4f, 21);
  for (const BvhConfig& c : test::all_configs()) {
    BvhImage image = build_bvh_image(mesh, c);
    TraversalUnit unit(image);
    TraversalState s;
    for (const Ray& ray : sample_random_rays(mesh, 100, 5)) {
      unit.trace(s, ray);
      uint64_t nodes = 0, triangles = 0;
      for (const MemoryAccess& a : s.accesses) {
        bool node = a.kind == AccessKind::Node;
        nodes += node;
        triangles += !node;
        uint64_t base = node ? image.node_base : image.triangle_base;
        uint64_t stride = node ? image.node_stride : image.triangle_stride;
        ASSERT_EQ((a.address - base) % stride, 0u);
      }
      EXPECT_EQ(nodes, s.counters.trav_nodes);
      EXPECT_EQ(triangles, s.counters.trav_prims);
    }
  }
}

}  // namespace
}  // namespace rtsim
