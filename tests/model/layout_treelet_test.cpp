// Node layouts (depth-first, breadth-first, treelet), addresses, and treelet formation.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "model/bvh/node_format.h"
#include "model_test_util.h"

namespace rtsim {
namespace {

// Parent position of every node, found by decoding the image from the root.
std::vector<int64_t> parents(const BvhImage& image) {
  std::vector<int64_t> parent(image.node_count, -2);
  parent[0] = -1;
  std::vector<uint32_t> stack{0};
  while (!stack.empty()) {
    uint32_t n = stack.back();
    stack.pop_back();
    NodeView view;
    decode_node(image.config.node_format, image.config.width, image.node_bytes(n), view, n,
                image.regions());
    for (int s = 0; s < view.slots; ++s) {
      if (!(view.valid & (1u << s)) || view.count[s] != 0) continue;
      EXPECT_EQ(parent[view.index[s]], -2) << "node reached twice";
      parent[view.index[s]] = n;
      stack.push_back(view.index[s]);
    }
  }
  return parent;
}

BvhConfig with_layout(BvhConfig c, NodeLayout layout, uint32_t treelet_bytes = 4096) {
  c.node_layout = layout;
  c.treelet_bytes = treelet_bytes;
  return c;
}

TEST(NodeLayout, EveryLayoutReachesEveryNodeOnce) {
  TriangleMesh mesh = test::random_soup(3000, 0.3f, 2);
  for (const BvhConfig& base : test::all_configs())
    for (NodeLayout layout :
         {NodeLayout::DepthFirst, NodeLayout::BreadthFirst, NodeLayout::Treelet}) {
      BvhImage image = build_bvh_image(mesh, with_layout(base, layout));
      auto parent = parents(image);
      for (uint32_t n = 0; n < image.node_count; ++n) ASSERT_NE(parent[n], -2) << n;
    }
}

TEST(NodeLayout, DepthFirstPutsFirstChildNextToParent) {
  TriangleMesh mesh = test::random_soup(3000, 0.3f, 2);
  BvhImage image = build_bvh_image(
      mesh, with_layout(test::config(NodeFormat::Aabb32, 4), NodeLayout::DepthFirst));
  auto parent = parents(image);
  // In pre-order, node i + 1 is a child of node i unless node i has no inner children.
  int adjacent = 0, inner = 0;
  for (uint32_t n = 0; n + 1 < image.node_count; ++n) {
    bool has_child = false;
    for (uint32_t m = 1; m < image.node_count && !has_child; ++m) has_child = parent[m] == n;
    inner += has_child;
    adjacent += has_child && parent[n + 1] == int64_t(n);
  }
  EXPECT_EQ(adjacent, inner);
}

TEST(NodeLayout, BreadthFirstOrdersByLevel) {
  TriangleMesh mesh = test::random_soup(3000, 0.3f, 2);
  for (NodeFormat f : {NodeFormat::Aabb32, NodeFormat::Cwbvh8}) {
    BvhImage image =
        build_bvh_image(mesh, with_layout(test::config(f, 4), NodeLayout::BreadthFirst));
    auto parent = parents(image);
    std::vector<int> level(image.node_count, 0);
    for (uint32_t n = 1; n < image.node_count; ++n) {
      ASSERT_LT(parent[n], int64_t(n)) << "a parent precedes its children";
      level[n] = level[parent[n]] + 1;
      EXPECT_GE(level[n], level[n - 1]) << "levels never decrease";
    }
  }
}

TEST(NodeLayout, TreeletLayoutKeepsTreeletsContiguous) {
  TriangleMesh mesh = test::random_soup(5000, 0.3f, 8);
  for (const BvhConfig& base : test::all_configs()) {
    BvhImage image = build_bvh_image(mesh, with_layout(base, NodeLayout::Treelet, 1024));
    for (uint32_t n = 1; n < image.node_count; ++n)
      ASSERT_GE(image.node_treelet[n], image.node_treelet[n - 1]);
    EXPECT_EQ(image.node_treelet.back() + 1, image.treelets.count);
  }
}

TEST(AddressSpace, RegionsAreAlignedAndDisjoint) {
  TriangleMesh mesh = test::random_soup(500, 0.3f, 1);
  BvhConfig c;
  c.node_base = 0x40000000;
  c.region_align = 65536;
  BvhImage image = build_bvh_image(mesh, c);
  EXPECT_EQ(image.node_address(0), 0x40000000u);
  EXPECT_EQ(image.node_address(3), 0x40000000u + 3 * 256);
  EXPECT_EQ(image.triangle_base % 65536, 0u);
  EXPECT_GE(image.triangle_base, image.node_base + image.nodes.size());
  EXPECT_EQ(image.triangle_address(2), image.triangle_base + 80);
}

TEST(AddressSpace, AlignedNodesNeverSpanMoreBlocksThanTheyFill) {
  TriangleMesh mesh = test::random_soup(500, 0.3f, 2);
  BvhConfig packed = test::config(NodeFormat::Cwbvh8, 8);
  for (uint32_t align : {32u, 64u, 128u}) {
    BvhConfig c = packed;
    c.node_align = align;
    BvhImage image = build_bvh_image(mesh, c);
    EXPECT_EQ(image.node_size, 80u);
    EXPECT_EQ(image.node_stride, align == 32 ? 96u : 128u) << align;
    for (uint32_t i = 0; i < image.node_count; ++i) {
      uint64_t first = image.node_address(i) / align;
      uint64_t last = (image.node_address(i) + image.node_size - 1) / align;
      ASSERT_EQ(last - first + 1, (image.node_size + align - 1) / align) << "node " << i;
    }
    EXPECT_EQ(image.node_padding_bytes(), uint64_t(image.node_count) * (image.node_stride - 80));
    EXPECT_EQ(image.node_count, build_bvh_image(mesh, packed).node_count) << "the same tree";
    for (int64_t parent : parents(image)) EXPECT_GE(parent, -1) << "every node is reachable";
  }
  BvhConfig bad = packed;
  bad.node_align = 96;
  EXPECT_NE(validate(bad).find("node_align is 96"), std::string::npos);
}

TEST(Treelets, RespectTheBudgetAndAreConnected) {
  TriangleMesh mesh = test::random_soup(20000, 0.2f, 6);
  uint32_t previous_count = 0;
  for (uint32_t budget : {512u, 4096u, 65536u}) {
    BvhImage image = build_bvh_image(
        mesh, with_layout(test::config(NodeFormat::Aabb32, 4), NodeLayout::Treelet, budget));
    const TreeletStats& s = image.treelets;
    EXPECT_EQ(s.oversized, 0u) << "single nodes always fit";
    EXPECT_LE(s.max_bytes, budget);
    EXPECT_EQ(s.total_bytes, image.nodes.size());
    EXPECT_EQ(std::accumulate(s.fill_histogram.begin(), s.fill_histogram.end(), 0u), s.count);
    if (previous_count) {
      EXPECT_LT(s.count, previous_count) << "a bigger budget, fewer treelets";
    }
    previous_count = s.count;
    // Connected: exactly one node per treelet has its parent outside it.
    auto parent = parents(image);
    std::vector<int> entries(s.count, 0);
    for (uint32_t n = 0; n < image.node_count; ++n)
      if (n == 0 || image.node_treelet[parent[n]] != image.node_treelet[n])
        entries[image.node_treelet[n]]++;
    for (int e : entries) ASSERT_EQ(e, 1);
  }
}

// Each treelet's nodes and their leaves' triangles, found by decoding the image.
std::vector<uint64_t> bytes_with_triangles(const BvhImage& image) {
  std::vector<uint64_t> bytes(image.treelets.count, 0);
  for (uint32_t n = 0; n < image.node_count; ++n) {
    NodeView view;
    decode_node(image.config.node_format, image.config.width, image.node_bytes(n), view, n,
                image.regions());
    uint64_t& b = bytes[image.node_treelet[n]];
    b += image.node_stride;
    for (int slot = 0; slot < view.slots; ++slot)
      if (view.valid & (1u << slot)) b += uint64_t(view.count[slot]) * image.triangle_stride;
  }
  return bytes;
}

TEST(Treelets, ABudgetOfNodesAndTrianglesCountsEachNodesLeafTriangles) {
  TriangleMesh mesh = test::random_soup(20000, 0.2f, 6);
  BvhConfig config = with_layout(test::config(NodeFormat::Aabb32, 4), NodeLayout::Treelet, 4096);
  BvhImage nodes_only = build_bvh_image(mesh, config);
  config.treelet_budget = TreeletBudget::NodesAndTriangles;
  BvhImage image = build_bvh_image(mesh, config);
  for (const BvhImage* i : {&nodes_only, &image}) {
    EXPECT_EQ(i->treelets.node_bytes, i->nodes.size());
    EXPECT_EQ(i->treelets.triangle_bytes, i->triangles.size()) << "each triangle in one leaf";
  }
  std::vector<uint64_t> loose = bytes_with_triangles(nodes_only);
  EXPECT_GT(*std::max_element(loose.begin(), loose.end()), 4096u)
      << "a budget of nodes only lets a treelet's triangles go over it";
  std::vector<uint64_t> bytes = bytes_with_triangles(image);
  for (uint64_t b : bytes) ASSERT_LE(b, 4096u);
  const TreeletStats& s = image.treelets;
  EXPECT_EQ(std::accumulate(bytes.begin(), bytes.end(), uint64_t(0)), s.total_bytes);
  EXPECT_EQ(s.total_bytes, image.nodes.size() + image.triangles.size());
  EXPECT_EQ(s.max_bytes, *std::max_element(bytes.begin(), bytes.end()));
  EXPECT_EQ(s.oversized, 0u);
  EXPECT_GT(s.count, nodes_only.treelets.count);
  EXPECT_NE(describe(image.config).find("4096 B with triangles"), std::string::npos);
}

TEST(Treelets, FirstTreeletIsTheRootAndFillsTheBudget) {
  TriangleMesh mesh = test::random_soup(20000, 0.2f, 6);
  BvhImage image = build_bvh_image(mesh, test::config(NodeFormat::Aabb32, 4));
  uint32_t in_first = 0;
  for (uint32_t t : image.node_treelet) in_first += t == 0;
  EXPECT_EQ(image.node_treelet[0], 0u);
  EXPECT_EQ(in_first, 4096u / 128u) << "32 nodes of 128 B fill 4 KB";
}

TEST(Treelets, Cwbvh8SiblingGroupsCanExceedSmallBudgets) {
  TriangleMesh mesh = test::random_soup(20000, 0.2f, 6);
  BvhImage image = build_bvh_image(
      mesh, with_layout(test::config(NodeFormat::Cwbvh8, 8), NodeLayout::Treelet, 512));
  EXPECT_GT(image.treelets.count, 0u);
  EXPECT_LE(image.treelets.max_bytes, 8u * 80u) << "at most one group of 8 siblings";
  EXPECT_EQ(image.treelets.fill_histogram[9] >= image.treelets.oversized, true);
}

}  // namespace
}  // namespace rtsim
