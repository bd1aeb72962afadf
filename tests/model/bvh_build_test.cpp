// BVH build: binned SAH invariants, wide collapse, determinism.
#include <gtest/gtest.h>

#include <algorithm>

#include "model/bvh/binned_sah.h"
#include "model/bvh/wide_bvh.h"
#include "model_test_util.h"
#include "traces/error.h"

namespace rtsim {
namespace {

bool contains(const Bounds& outer, const Bounds& inner) {
  return outer.lo.x <= inner.lo.x && outer.lo.y <= inner.lo.y && outer.lo.z <= inner.lo.z &&
         outer.hi.x >= inner.hi.x && outer.hi.y >= inner.hi.y && outer.hi.z >= inner.hi.z;
}

TEST(BinnedSah, EveryTriangleInExactlyOneLeafWithinLeafSize) {
  TriangleMesh mesh = test::random_soup(5000, 0.3f, 7);
  for (int bins : {16, 32})
    for (int leaf : {1, 3, 8}) {
      BvhConfig c;
      c.sah_bins = bins;
      c.max_leaf_size = leaf;
      Bvh2 bvh = build_binned_sah(mesh, c);
      std::vector<int> seen(mesh.triangle_count(), 0);
      for (const Bvh2Node& node : bvh.nodes) {
        if (!node.leaf()) {
          EXPECT_TRUE(contains(node.box, bvh.nodes[node.first].box));
          EXPECT_TRUE(contains(node.box, bvh.nodes[node.first + 1].box));
          continue;
        }
        EXPECT_LE(node.count, uint32_t(leaf)) << "bins " << bins;
        for (uint32_t i = node.first; i < node.first + node.count; ++i) seen[bvh.prim_order[i]]++;
      }
      EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int s) { return s == 1; }));
      EXPECT_LT(bvh.depth, 40u) << "a binned SAH tree over 5000 triangles stays shallow";
    }
}

TEST(BinnedSah, IdenticalCentroidsStillSplitToLeafSize) {
  TriangleMesh mesh;
  for (int i = 0; i < 100; ++i) test::add_triangle(mesh, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  Bvh2 bvh = build_binned_sah(mesh, BvhConfig{});
  for (const Bvh2Node& node : bvh.nodes)
    if (node.leaf()) {
      EXPECT_LE(node.count, 3u);
    }
  EXPECT_LE(bvh.depth, 8u) << "halving by index keeps the depth logarithmic";
}

TEST(WideCollapse, WidthBoundsChildrenAndCoversAllTriangles) {
  TriangleMesh mesh = test::random_soup(3000, 0.3f, 3);
  Bvh2 bvh2 = build_binned_sah(mesh, BvhConfig{});
  for (int width : {2, 4, 6, 8}) {
    WideBvh wide = collapse_bvh(bvh2, width);
    std::vector<int> seen(mesh.triangle_count(), 0);
    size_t slots = 0;
    for (const WideNode& node : wide.nodes) {
      EXPECT_LE(node.child_count, width);
      EXPECT_GE(node.child_count, 2);
      slots += node.child_count;
      for (int c = 0; c < node.child_count; ++c) {
        const WideChild& child = node.child[c];
        EXPECT_TRUE(contains(node.box, child.box));
        if (!child.leaf()) continue;
        for (uint32_t i = child.first; i < child.first + child.count; ++i)
          seen[wide.prim_order[i]]++;
      }
    }
    EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int s) { return s == 1; }));
    EXPECT_GT(double(slots) / wide.nodes.size(), 0.55 * width) << "nodes are mostly full";
  }
}

TEST(WideCollapse, SingleTriangleGivesRootWithOneLeaf) {
  TriangleMesh mesh;
  test::add_triangle(mesh, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  WideBvh wide = collapse_bvh(build_binned_sah(mesh, BvhConfig{}), 8);
  ASSERT_EQ(wide.nodes.size(), 1u);
  EXPECT_EQ(wide.nodes[0].child_count, 1);
  EXPECT_TRUE(wide.nodes[0].child[0].leaf());
}

TEST(BvhImage, BuildIsDeterministic) {
  TriangleMesh mesh = test::random_soup(2000, 0.5f, 11);
  for (const BvhConfig& c : test::all_configs()) {
    BvhImage a = build_bvh_image(mesh, c), b = build_bvh_image(mesh, c);
    EXPECT_EQ(a.nodes, b.nodes);
    EXPECT_EQ(a.triangles, b.triangles);
    EXPECT_EQ(a.node_treelet, b.node_treelet);
  }
}

TEST(BvhImage, RejectsImpossibleConfigs) {
  TriangleMesh mesh = test::random_soup(10, 0.5f, 1);
  BvhConfig c;
  c.width = 9;
  EXPECT_THROW(build_bvh_image(mesh, c), InputError);
  c = test::config(NodeFormat::Cwbvh8, 8, 4);
  EXPECT_THROW(build_bvh_image(mesh, c), InputError) << "cwbvh8 leaves hold 3 triangles";
  c = BvhConfig{};
  c.sah_bins = 8;
  EXPECT_THROW(build_bvh_image(mesh, c), InputError);
  c = BvhConfig{};
  c.treelet_bytes = 256;
  EXPECT_THROW(build_bvh_image(mesh, c), InputError);
}

}  // namespace
}  // namespace rtsim
