// Intel Xe records (model/bvh/intel_nodes.h): sizes equal to Mesa's anv driver, the bytes of a
// node, a quad and an instance leaf, conservative quantised boxes, children in one run after
// their node, and traversal answers equal to the uncompressed format's.
#include "model/bvh/intel_nodes.h"

#include <gtest/gtest.h>

#include <set>

#include "model/bvh/intel_layout.h"
#include "model/bvh/triangle_format.h"
#include "model_test_util.h"

namespace rtsim {
namespace {

BvhConfig xe_config(int leaf = 2) {
  BvhConfig c = test::config(NodeFormat::Xe6, 6, leaf);
  c.triangle_format = TriangleFormat::XeQuad;
  return c;
}

TEST(IntelFormat, SizesAreTheDriversStaticAsserts) {
  // anv_bvh.h: ANV_RT_BLOCK_SIZE 64, INTERNAL_NODE_SIZE and QUAD_LEAF_SIZE one block,
  // INSTANCE_LEAF_SIZE two; traversal reads the instance leaf's first 64 bytes (part0).
  EXPECT_EQ(kXeBlockBytes, 64u);
  EXPECT_EQ(sizeof(XeInternalNode), 64u);
  EXPECT_EQ(sizeof(XeQuadLeaf), 64u);
  EXPECT_EQ(2 * sizeof(XeInstanceLeafPart), 128u);
  EXPECT_EQ(kXeInstanceReadBytes, 64u);
  EXPECT_EQ(kXeInstanceReadBytes, kInstanceRecordBytes) << "the same read as rtsim's record";
  EXPECT_EQ(node_stride(NodeFormat::Xe6, 6), 64u);
  EXPECT_EQ(triangle_stride(TriangleFormat::XeQuad), 64u);
  EXPECT_EQ(offsetof(XeInternalNode, child_data), 22u);
  EXPECT_EQ(offsetof(XeInternalNode, lower_x), 28u);
  EXPECT_EQ(offsetof(XeQuadLeaf, v), 16u);
}

TEST(IntelFormat, ConfigsOutsideTheFormatAreRefused) {
  BvhConfig c = xe_config();
  EXPECT_EQ(validate(c), "");
  c.width = 8;
  EXPECT_NE(validate(c).find("at most 6 children"), std::string::npos);
  c = xe_config(3);
  EXPECT_NE(validate(c).find("at most 2 triangles"), std::string::npos);
  c = xe_config();
  c.triangle_format = TriangleFormat::Raw;
  EXPECT_NE(validate(c).find("go together"), std::string::npos);
}

TEST(IntelFormat, QuadOfTwoTrianglesSharingAnEdge) {
  TriangleMesh mesh;
  test::add_triangle(mesh, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  test::add_triangle(mesh, {1, 0, 0}, {1, 1, 0}, {0, 1, 0});
  test::add_triangle(mesh, {5, 5, 5}, {6, 5, 5}, {5, 6, 5});
  uint8_t quad[64];
  uint32_t second = 1;
  ASSERT_TRUE(encode_xe_quad(mesh, 0, &second, quad));
  uint32_t words[4];
  std::memcpy(words, quad, 16);
  EXPECT_EQ(words[0], 0xff000000u) << "geometry mask 0xff";
  EXPECT_EQ(words[1], (1u << 29) | (1u << 30)) << "opacity culling off, opaque";
  EXPECT_EQ(words[2], 0u) << "prim_index0";
  // Delta 1; the second triangle's corners are v1, v3 (the new one), v2; last quad.
  EXPECT_EQ(words[3], 1u | 1u << 16 | 3u << 18 | 2u << 20 | 1u << 22);
  EXPECT_EQ(xe_quad_triangles(quad), 2u);
  float v[9];
  EXPECT_EQ(xe_quad_corners(quad, 1, v), 1u);
  EXPECT_EQ(glm::vec3(v[3], v[4], v[5]), glm::vec3(1, 1, 0));
  second = 2;
  EXPECT_FALSE(encode_xe_quad(mesh, 0, &second, quad)) << "no shared edge: two quads";
  ASSERT_TRUE(encode_xe_quad(mesh, 2, nullptr, quad));
  EXPECT_EQ(xe_quad_triangles(quad), 1u) << "second triangle off, as Mesa writes it";
}

TEST(IntelFormat, NodeBytesAndChildrenInOneRun) {
  TriangleMesh mesh = test::random_soup(3000, 0.3f, 4);
  for (NodeLayout layout :
       {NodeLayout::DepthFirst, NodeLayout::BreadthFirst, NodeLayout::Treelet}) {
    BvhConfig c = xe_config();
    c.node_layout = layout;
    BvhImage image = build_bvh_image(mesh, c);
    EXPECT_TRUE(image.interleaved);
    EXPECT_EQ(image.triangle_base, image.node_base);
    EXPECT_EQ(image.triangle_count, 3000u);
    std::multiset<uint32_t> prims;
    uint32_t nodes = 0;
    for (uint32_t p = 0; p < image.positions(); ++p) {
      if (!image.holds_node(p)) continue;
      nodes++;
      const uint8_t* bytes = image.node_bytes(p);
      NodeView view;
      decode_node(NodeFormat::Xe6, 6, bytes, view, p);
      uint32_t first;
      std::memcpy(&first, bytes + 12, 4);
      ASSERT_GT(first, 0u) << "children follow their node";
      EXPECT_EQ(bytes[21], 0xff) << "node mask";
      uint32_t next = p + first;
      for (int s = 0; s < kXeNodeSlots; ++s) {
        if (!(view.valid >> s & 1)) {
          EXPECT_EQ(bytes[28 + s], 0x80) << "an empty slot's lower_x";
          continue;
        }
        EXPECT_EQ(view.index[s], next) << "children are one run";
        next += bytes[22 + s] & 3;
        EXPECT_EQ(image.holds_node(view.index[s]), view.count[s] == 0);
        for (uint32_t q = 0; q < view.count[s]; ++q) {
          const uint8_t* quad = image.triangle_bytes(view.index[s] + q);
          for (uint32_t k = 0; k < xe_quad_triangles(quad); ++k) {
            float v[9];
            prims.insert(xe_quad_corners(quad, k, v));
            for (int corner = 0; corner < 3; ++corner)
              for (int a = 0; a < 3; ++a) {  // quantised boxes hold their triangles
                ASSERT_LE(view.lo[a][s], v[3 * corner + a]);
                ASSERT_GE(view.hi[a][s], v[3 * corner + a]);
              }
          }
          uint32_t delta;
          std::memcpy(&delta, quad + 12, 4);
          EXPECT_EQ((delta >> 22) & 1, q + 1 == view.count[s]) << "last quad of the leaf";
        }
      }
    }
    EXPECT_EQ(nodes, image.node_count);
    EXPECT_EQ(prims.size(), 3000u);
    EXPECT_EQ(std::set<uint32_t>(prims.begin(), prims.end()).size(), 3000u) << "each once";
  }
}

TEST(IntelFormat, TraversalAnswersAsTheUncompressedFormat) {
  TriangleMesh mesh = test::random_soup(2000, 0.4f, 11);
  for (auto& p : mesh.positions) p = p + glm::vec3(300.0f, -20.0f, 500.0f);  // off the origin
  BvhImage exact = build_bvh_image(mesh, test::config(NodeFormat::Aabb32, 6, 2));
  for (int leaf : {1, 2}) {
    BvhImage xe = build_bvh_image(mesh, xe_config(leaf));
    TraversalUnit a(exact), b(xe);
    TraversalState sa, sb;
    size_t hits = 0;
    for (const Ray& ray : sample_random_rays(mesh, 2000, 7)) {
      Hit ha = a.trace(sa, ray), hb = b.trace(sb, ray);
      ASSERT_EQ(ha.prim, hb.prim);
      ASSERT_EQ(ha.t, hb.t);
      hits += ha.prim != kNoHit;
    }
    EXPECT_GT(hits, 300u);
  }
}

TEST(IntelFormat, InstanceLeafKeepsBothTransforms) {
  InstanceRecord r;
  r.to_world.linear = glm::mat3(2.0f);
  r.to_world.offset = glm::vec3(1, 2, 3);
  r.to_object = inverse(r.to_world);
  r.instance = 7;
  r.mask = 0x21;
  uint8_t leaf[128];
  encode_xe_instance(r, 0x123456789abcull, leaf);
  EXPECT_EQ(leaf[3], 0x21) << "geometry mask in DW0's top byte";
  EXPECT_EQ(xe_instance_root(leaf), 0x123456789abcull);
  uint64_t part1_root;
  std::memcpy(&part1_root, leaf + 64, 8);
  EXPECT_EQ(part1_root, 0x123456789abcull) << "part1's bvh_ptr";
  uint64_t root;
  InstanceRecord back = decode_xe_instance(leaf, root);
  EXPECT_EQ(back.instance, 7u);
  EXPECT_EQ(back.to_object.linear, r.to_object.linear);
  EXPECT_EQ(back.to_object.offset, r.to_object.offset);
  glm::vec3 p;
  std::memcpy(&p, leaf + 52, 12);
  EXPECT_EQ(p, glm::vec3(1, 2, 3)) << "part0 ends with the object-to-world translation";
}

}  // namespace
}  // namespace rtsim
