// Node and triangle formats: exact byte sizes, conservative cwbvh8 quantization, contiguity.
#include "model/bvh/node_format.h"

#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>

#include "model/bvh/triangle_format.h"
#include "model_test_util.h"

namespace rtsim {
namespace {

TEST(NodeFormat, ByteSizes) {
  EXPECT_EQ(node_stride(NodeFormat::Aabb32, 2), 64u);
  EXPECT_EQ(node_stride(NodeFormat::Aabb32, 4), 128u);
  EXPECT_EQ(node_stride(NodeFormat::Aabb32, 6), 192u);
  EXPECT_EQ(node_stride(NodeFormat::Aabb32, 8), 256u);
  for (int w : {2, 4, 6, 8}) EXPECT_EQ(node_stride(NodeFormat::Cwbvh8, w), 80u);
  EXPECT_EQ(triangle_stride(TriangleFormat::Raw), 40u);
  EXPECT_EQ(triangle_stride(TriangleFormat::Woop), 52u);
}

TEST(NodeFormat, ImageSizesAreExact) {
  TriangleMesh mesh = test::random_soup(1000, 0.4f, 5);
  for (const BvhConfig& c : test::all_configs()) {
    BvhImage image = build_bvh_image(mesh, c);
    EXPECT_EQ(image.nodes.size(), size_t(image.node_count) * image.node_stride);
    EXPECT_EQ(image.triangles.size(), 1000u * triangle_stride(c.triangle_format));
    EXPECT_EQ(image.triangle_count, 1000u);
  }
}

// Every triangle of a leaf lies inside the leaf's decoded box, for both formats: quantized
// boxes are rounded outward and stay conservative.
TEST(NodeFormat, DecodedLeafBoxesContainTheirTriangles) {
  TriangleMesh mesh = test::random_soup(4000, 0.2f, 9);
  // Far from the origin too, where rounding the quantized planes matters most.
  TriangleMesh far = mesh;
  for (auto& p : far.positions) p = p * 0.001f + glm::vec3(1e5f, -3e4f, 7e6f);
  for (const TriangleMesh* m : {&mesh, &far})
    for (const BvhConfig& c : test::all_configs()) {
      BvhImage image = build_bvh_image(*m, c);
      size_t checked = 0;
      for (uint32_t n = 0; n < image.node_count; ++n) {
        NodeView view;
        decode_node(c.node_format, c.width, image.node_bytes(n), view, n, image.regions());
        for (int s = 0; s < view.slots; ++s) {
          if (!(view.valid & (1u << s)) || view.count[s] == 0) continue;
          for (uint32_t t = 0; t < view.count[s]; ++t) {
            float v[9];
            std::memcpy(v, image.triangle_bytes(view.index[s] + t), 36);
            for (int k = 0; k < 3; ++k)
              for (int a = 0; a < 3; ++a) {
                ASSERT_LE(view.lo[a][s], v[3 * k + a]) << node_format_name(c.node_format);
                ASSERT_GE(view.hi[a][s], v[3 * k + a]) << node_format_name(c.node_format);
              }
            checked++;
          }
        }
      }
      EXPECT_EQ(checked, m->triangle_count()) << "every triangle sits in exactly one leaf";
    }
}

TEST(NodeFormat, QuantizedBoxesAreTight) {
  TriangleMesh mesh = test::random_soup(2000, 0.2f, 4);
  BvhImage image = build_bvh_image(mesh, test::config(NodeFormat::Cwbvh8, 8));
  double grown = 0.0, total = 0.0;
  for (uint32_t n = 0; n < image.node_count; ++n) {
    NodeView view;
    decode_cwbvh8(image.node_bytes(n), view);
    float parent_extent = 0.0f;
    for (int s = 0; s < 8; ++s)
      if (view.valid & (1u << s))
        parent_extent = std::max(parent_extent, view.hi[0][s] - view.lo[0][0]);
    for (int s = 0; s < 8; ++s)
      if (view.valid & (1u << s)) {
        total += 1.0;
        grown += (view.hi[0][s] - view.lo[0][s]) / std::max(parent_extent, 1e-30f);
      }
  }
  EXPECT_LT(grown / total, 0.6) << "child boxes are a fraction of the node, not the node";
}

TEST(NodeFormat, Cwbvh8RejectsScatteredSiblings) {
  WideNode node;
  node.child_count = 2;
  node.box.grow(glm::vec3(0));
  node.box.grow(glm::vec3(1));
  for (int c = 0; c < 2; ++c) {
    node.child[c].box = node.box;
    node.child[c].node = uint32_t(c + 1);
  }
  ChildPlacement placement;
  placement.position[0] = 5;
  placement.position[1] = 9;
  uint8_t bytes[kCwbvhNodeBytes];
  EXPECT_THROW(encode_node(NodeFormat::Cwbvh8, 8, node, placement, bytes), std::logic_error);
  placement.position[1] = 6;
  EXPECT_NO_THROW(encode_node(NodeFormat::Cwbvh8, 8, node, placement, bytes));
  NodeView view;
  decode_cwbvh8(bytes, view);
  EXPECT_EQ(view.valid, 3u);
  EXPECT_EQ(view.index[0], 5u);
  EXPECT_EQ(view.index[1], 6u);
  EXPECT_EQ(view.count[1], 0u);
}

TEST(TriangleFormat, RawRecordHoldsVerticesAndId) {
  TriangleMesh mesh;
  test::add_triangle(mesh, {1, 2, 3}, {4, 5, 6}, {7, 8, 9});
  uint8_t bytes[kRawTriangleBytes];
  encode_triangle(TriangleFormat::Raw, mesh, 0, bytes);
  float v[9];
  uint32_t id;
  std::memcpy(v, bytes, 36);
  std::memcpy(&id, bytes + 36, 4);
  EXPECT_EQ(v[0], 1.0f);
  EXPECT_EQ(v[8], 9.0f);
  EXPECT_EQ(id, 0u);
}

}  // namespace
}  // namespace rtsim
