// AMD RDNA2/3 records (model/bvh/amd_nodes.h, amd_instances.h): sizes equal radv's static
// asserts, the bytes of each record sit at radv's struct offsets, fp16 boxes round outward, and
// the instance node is what an instance step reads. Traversal against Embree with these formats
// runs in the shared suites (test::all_configs: hardcases_test, traversal_test, ...).
#include "model/bvh/amd_nodes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "model/bvh/amd_instances.h"
#include "model/bvh/node_format.h"
#include "model/bvh/triangle_format.h"
#include "model/units/traversal.h"
#include "model_test_util.h"
#include "tests/alpha_layers.h"
#include "tests/instanced_world.h"

namespace rtsim {
namespace {

uint32_t u32_at(const uint8_t* bytes, size_t offset) {
  uint32_t v;
  std::memcpy(&v, bytes + offset, 4);
  return v;
}

float f32_at(const uint8_t* bytes, size_t offset) {
  float v;
  std::memcpy(&v, bytes + offset, 4);
  return v;
}

uint16_t u16_at(const uint8_t* bytes, size_t offset) {
  uint16_t v;
  std::memcpy(&v, bytes + offset, 2);
  return v;
}

// radv_GetAccelerationStructureBuildSizesKHR (src/amd/vulkan/radv_acceleration_structure.c):
// STATIC_ASSERT(sizeof(struct radv_bvh_triangle_node) == 64), instance_node == 128,
// box16_node == 64, box32_node == 128.
TEST(AmdNodes, SizesEqualRadvStaticAsserts) {
  EXPECT_EQ(node_stride(NodeFormat::AmdBox32, 4), 128u);
  EXPECT_EQ(node_stride(NodeFormat::AmdBox16, 4), 64u);
  EXPECT_EQ(triangle_stride(TriangleFormat::AmdTriangle), 64u);
  EXPECT_EQ(instance_record_bytes(NodeFormat::AmdBox32), 128u);
  EXPECT_EQ(instance_record_bytes(NodeFormat::AmdBox16), 128u);
  EXPECT_EQ(instance_fetch_bytes(NodeFormat::AmdBox32), 64u);
  TriangleMesh mesh = test::random_soup(300, 0.3f, 4);
  for (NodeFormat f : {NodeFormat::AmdBox32, NodeFormat::AmdBox16}) {
    BvhImage image = build_bvh_image(mesh, test::amd_config(f));
    EXPECT_EQ(image.node_size, node_stride(f, 4));
    EXPECT_EQ(image.node_stride, image.node_size) << "power-of-two records need no padding";
    EXPECT_EQ(image.triangles.size(), 300u * 64u);
  }
}

// Node 2 is an inner child, triangles 3 and 7 are leaves; the leaf records start 4096 bytes
// after the first node.
WideNode three_children(RecordRegions& regions, ChildPlacement& placement) {
  WideNode node;
  node.child_count = 3;
  node.child[0].box = {{0.5f, -1.0f, 2.0f}, {1.5f, 0.0f, 3.0f}};
  node.child[1].box = {{0.1f, 0.2f, -70000.0f}, {0.3f, 0.4f, 70000.0f}};
  node.child[2].box = {{-2.0f, -2.0f, -2.0f}, {2.0f, 2.0f, 2.0f}};
  node.child[0].node = 9;
  node.child[1].count = 1;
  node.child[2].count = 1;
  placement.position[0] = 2;
  placement.position[1] = 3;
  placement.position[2] = 7;
  regions.leaf_offset = 4096;
  regions.leaf_stride = 64;
  return node;
}

TEST(AmdNodes, Box32BytesAreRadvBox32Node) {
  RecordRegions regions;
  ChildPlacement placement;
  regions.node_stride = 128;
  WideNode node = three_children(regions, placement);
  uint8_t bytes[128];
  encode_node(NodeFormat::AmdBox32, 4, node, placement, bytes, regions);
  // children[4]: pack_node_id(offset, type) = offset >> 3 | type.
  EXPECT_EQ(u32_at(bytes, 0), (2u * 128u >> 3) | kAmdTypeBox32);
  EXPECT_EQ(u32_at(bytes, 4), (4096u + 3u * 64u) >> 3);
  EXPECT_EQ(u32_at(bytes, 8), (4096u + 7u * 64u) >> 3);
  EXPECT_EQ(u32_at(bytes, 12), kAmdInvalidNode);
  // coords[4]: vk_aabb {min xyz, max xyz} at 16 + 24 * child; NaN for the empty slot.
  for (int c = 0; c < 3; ++c)
    for (int a = 0; a < 3; ++a) {
      EXPECT_EQ(f32_at(bytes, 16 + 24 * c + 4 * a), node.child[c].box.lo[a]);
      EXPECT_EQ(f32_at(bytes, 16 + 24 * c + 12 + 4 * a), node.child[c].box.hi[a]);
    }
  for (int k = 0; k < 6; ++k) EXPECT_TRUE(std::isnan(f32_at(bytes, 16 + 72 + 4 * k)));
  for (size_t at = kAmdBox32Flags; at < 128; at += 4)
    EXPECT_EQ(u32_at(bytes, at), 0u)
        << "flags come with the leaf records (set_amd_box_flags); reserved stays 0";
  // The decoder gets the positions back.
  NodeView view;
  decode_node(NodeFormat::AmdBox32, 4, bytes, view, 0, regions);
  EXPECT_EQ(view.valid, 0x7u);
  EXPECT_EQ(view.index[0], 2u);
  EXPECT_EQ(view.count[0], 0u);
  EXPECT_EQ(view.index[1], 3u);
  EXPECT_EQ(view.count[1], 1u);
  EXPECT_EQ(view.index[2], 7u);
  EXPECT_EQ(view.lo[1][1], 0.2f) << "child 1, axis y";
}

// The flags word of a built level: per triangle child ONLY_OPAQUE or NO_OPAQUE (alpha-tested),
// 0 for inner children and empty slots.
TEST(AmdNodes, Box32FlagsMarkEachTriangleChildsOpacity) {
  TriangleMesh mesh = test::layered(3);  // 6 alpha-tested triangles, then 2 opaque ones
  BvhImage image = build_bvh_image(mesh, test::amd_config(NodeFormat::AmdBox32));
  size_t opaque = 0, alpha_tested = 0;
  for (uint32_t n = 0; n < image.node_count; ++n) {
    const uint8_t* node = image.node_bytes(n);
    NodeView view;
    decode_node(NodeFormat::AmdBox32, 4, node, view, n, image.regions());
    uint32_t expected = 0;
    for (int c = 0; c < 4; ++c) {
      if (!(view.valid & (1u << c)) || view.count[c] == 0) continue;
      uint32_t prim = u32_at(image.triangle_bytes(view.index[c]), kAmdTriangleId);
      bool tested = mesh.alpha->tested(prim);
      expected |= (tested ? kAmdBoxNoOpaque : kAmdBoxOnlyOpaque) << (8 * c);
      (tested ? alpha_tested : opaque)++;
    }
    EXPECT_EQ(u32_at(node, kAmdBox32Flags), expected) << "node " << n;
  }
  EXPECT_EQ(alpha_tested, 6u);
  EXPECT_EQ(opaque, 2u);
}

TEST(AmdNodes, Box16BytesAreRadvBox16NodeRoundedOutward) {
  RecordRegions regions;
  ChildPlacement placement;
  regions.node_stride = 64;
  regions.instance_leaves = true;
  WideNode node = three_children(regions, placement);
  uint8_t bytes[64];
  encode_node(NodeFormat::AmdBox16, 4, node, placement, bytes, regions);
  EXPECT_EQ(u32_at(bytes, 0), (2u * 64u >> 3) | kAmdTypeBox16);
  EXPECT_EQ(u32_at(bytes, 4), ((4096u + 3u * 64u) >> 3) | kAmdTypeInstance);
  // coords[4][2][3] float16 at 16 + 12 * child: 0.5 = 0x3800, 1.5 = 0x3e00 exactly.
  EXPECT_EQ(u16_at(bytes, 16), 0x3800u);
  EXPECT_EQ(u16_at(bytes, 16 + 6), 0x3e00u);
  // 0.1 lies between halves 0x2e66 and 0x2e67: min goes down, 0.3's max goes up.
  EXPECT_EQ(u16_at(bytes, 28), 0x2e66u);
  EXPECT_LT(half_to_float(0x2e66), 0.1f);
  EXPECT_GT(half_to_float(u16_at(bytes, 28 + 6)), 0.3f);
  // Beyond the largest half (65504): min -inf, max +inf.
  EXPECT_EQ(half_to_float(u16_at(bytes, 28 + 4)), -std::numeric_limits<float>::infinity());
  EXPECT_EQ(half_to_float(u16_at(bytes, 28 + 10)), std::numeric_limits<float>::infinity());
  NodeView view;
  decode_node(NodeFormat::AmdBox16, 4, bytes, view, 0, regions);
  EXPECT_EQ(view.valid, 0x7u);
  EXPECT_EQ(view.index[1], 3u);
  for (int c = 0; c < 3; ++c)
    for (int a = 0; a < 3; ++a) {
      EXPECT_LE(view.lo[a][c], node.child[c].box.lo[a]);
      EXPECT_GE(view.hi[a][c], node.child[c].box.hi[a]);
    }
}

// Rounding outward is what keeps fp16 boxes conservative; rounding to nearest would not be:
// 0.1's nearest half lies below it, so a max plane rounded to nearest would cut the box.
TEST(AmdNodes, HalfRoundingBracketsEveryValue) {
  SeededRandom random(11);
  for (int i = 0; i < 200000; ++i) {
    float magnitude = std::ldexp(random.uniform() + 0.5f, int(random.uniform() * 60.0f) - 30);
    float v = random.uniform() < 0.5f ? -magnitude : magnitude;
    float down = half_to_float(half_round_down(v)), up = half_to_float(half_round_up(v));
    ASSERT_LE(down, v) << v;
    ASSERT_GE(up, v) << v;
    // Tight: the bracket is at most one half step wide.
    int step = std::abs(int(half_round_up(v) & 0x7fff) - int(half_round_down(v) & 0x7fff));
    ASSERT_LE(step, 1) << v;
  }
  for (float exact : {0.0f, 1.0f, -2.5f, 65504.0f, 0x1p-24f, -0x1p-14f}) {
    EXPECT_EQ(half_to_float(half_round_down(exact)), exact);
    EXPECT_EQ(half_to_float(half_round_up(exact)), exact);
  }
}

TEST(AmdNodes, TriangleBytesAreRadvTriangleNode) {
  TriangleMesh mesh;
  test::add_triangle(mesh, {1, 2, 3}, {4, 5, 6}, {7, 8, 9.5f});
  uint8_t bytes[64];
  std::memset(bytes, 0xab, sizeof bytes);
  encode_triangle(TriangleFormat::AmdTriangle, mesh, 0, bytes);
  for (int k = 0; k < 9; ++k) EXPECT_EQ(f32_at(bytes, 4 * k), k == 8 ? 9.5f : float(k + 1));
  for (size_t at : {36, 40, 44, 56}) EXPECT_EQ(u32_at(bytes, at), 0u) << "reserved at " << at;
  EXPECT_EQ(u32_at(bytes, 48), 0u) << "triangle_id";
  EXPECT_EQ(u32_at(bytes, 52), kAmdGeometryOpaque) << "geometry 0, opaque";
  EXPECT_EQ(u32_at(bytes, 60), 9u) << "barycentrics control as radv_encode_triangle_gfx10_3";
}

TEST(AmdNodes, InstanceNodesAreRadvInstanceNodesAndStepsReadTheirFirst64Bytes) {
  InstancedMesh g = test::instanced_world();
  TwoLevelBvh bvh = build_two_level_bvh(g, test::amd_config(NodeFormat::AmdBox32));
  ASSERT_EQ(bvh.top.triangle_stride, 128u);
  for (uint32_t p = 0; p < bvh.top.triangle_count; ++p) {
    const uint8_t* node = bvh.top.triangle_bytes(p);
    uint32_t instance = u32_at(node, 64);
    ASSERT_LT(instance, g.instances.size());
    const Instance& inst = g.instances[instance];
    uint64_t bvh_ptr;
    std::memcpy(&bvh_ptr, node, 8);
    EXPECT_EQ(bvh_ptr, bvh.bottom[inst.mesh].node_base >> 3) << "addr_to_node(BLAS root)";
    EXPECT_EQ(u32_at(node, 8), instance | (uint32_t(inst.mask) << 24));
    // otw_matrix row 0 at 80: (linear row 0, offset x).
    EXPECT_EQ(f32_at(node, 80 + 12), inst.to_world.offset.x);
    EXPECT_EQ(f32_at(node, 80 + 4), inst.to_world.linear[1][0]);
    InstanceRecord r = read_instance_record(bvh.top, p, &bvh.bottom);
    EXPECT_EQ(r.blas, inst.mesh);
    EXPECT_EQ(r.instance, instance);
  }
  TraversalUnit unit(bvh);
  TraversalState state;
  size_t instance_reads = 0;
  glm::vec3 center = 0.5f * (bvh.top.scene_lo + bvh.top.scene_hi);
  glm::vec3 size = bvh.top.scene_hi - bvh.top.scene_lo;
  for (int i = 0; i < 64; ++i) {
    glm::vec3 target = center + size * glm::vec3((i % 8) / 8.0f - 0.45f, (i / 8) / 8.0f - 0.45f, 0);
    Ray ray = test::ray_to(center + glm::vec3(0, 0, 3 * size.z + 1), target);
    unit.trace(state, ray);
    for (const MemoryAccess& a : state.accesses)
      if (a.kind == AccessKind::Instance) {
        EXPECT_EQ(a.bytes, kAmdInstanceFetchBytes);
        instance_reads++;
      }
  }
  EXPECT_GT(instance_reads, 0u);
}

TEST(AmdNodes, ConfigNamesWhatAmdNodesNeed) {
  BvhConfig c = test::amd_config(NodeFormat::AmdBox32);
  EXPECT_EQ(validate(c), "");
  c.width = 8;
  EXPECT_NE(validate(c).find("width is 8"), std::string::npos) << validate(c);
  c = test::amd_config(NodeFormat::AmdBox16);
  c.max_leaf_size = 3;
  EXPECT_NE(validate(c).find("max_leaf_size is 3"), std::string::npos) << validate(c);
  c = test::amd_config(NodeFormat::AmdBox16);
  c.triangle_format = TriangleFormat::Raw;
  EXPECT_NE(validate(c).find("amd_tri"), std::string::npos) << validate(c);
  EXPECT_EQ(node_format_from_name("amd_box16"), NodeFormat::AmdBox16);
  EXPECT_EQ(triangle_format_from_name("amd_tri"), TriangleFormat::AmdTriangle);
}

}  // namespace
}  // namespace rtsim
