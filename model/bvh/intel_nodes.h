// Intel Xe ray-tracing BVH records, byte for byte as Mesa's Vulkan driver (anv) writes them for
// the RT unit of Xe-HPG and Xe2 (src/intel/vulkan/bvh/anv_bvh.h, read at mirror/mesa commit
// e5302d19; the encoder is src/intel/vulkan/bvh/encode.comp):
//  - xe6 internal node (`struct anv_internal_node`, ANV_RT_INTERNAL_NODE_SIZE = 64 B): the fp32
//    origin of the quantisation grid, child_block_offset (64-byte blocks from this node to its
//    first child), node_type, a power-of-two exponent per axis, the node mask, one child_data
//    byte per slot (blockIncr: the child's size in 64-byte blocks; startPrim: its type in a mixed
//    node) and six 8-bit quantised lower and upper planes per axis. A plane is origin + q *
//    2^(exp - 8) (encode.comp, quantize_bounds). An empty slot has lower_x = 0x80, upper_x = 0.
//    The children of a node lie one after another from child_block_offset, each blockIncr blocks.
//  - xe_quad leaf (`struct anv_quad_leaf_node`, ANV_RT_QUAD_LEAF_SIZE = 64 B): the leaf
//    descriptor (shader index and geometry mask; geometry id and flags), prim_index0, then
//    prim_index1_delta (16-bit id delta of the second triangle, three 2-bit vertex indices, the
//    "last quad in the leaf" bit 22) and four fp32 vertices: two triangles sharing four vertices.
//    Mesa's encoder writes one triangle a quad (indices 0,0,0: second triangle off); rtsim pairs
//    a leaf's two triangles into one quad when they share an edge, as the format allows.
//  - instance leaf (`struct anv_instance_leaf`, ANV_RT_INSTANCE_LEAF_SIZE = 128 B): part0 (the
//    64 bytes traversal reads: geometry mask, flags, the 48-bit start node pointer of the BLAS,
//    the world-to-object 3x3 by columns and the object-to-world translation) and part1 (the
//    64 bytes shading reads: BLAS pointer, instance id and index, the object-to-world 3x3 and
//    the world-to-object translation).
// Layout: the node region holds internal nodes and leaves interleaved in 64-byte blocks (the
// "interleaving internal nodes and leaves" of anv_bvh.h's bvh_layout), so a node's children,
// inner ones first, then its leaves, are one contiguous run. Not modelled: the 256-byte
// anv_accel_struct_header before the root and the TLAS's table of instance leaf pointers.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

#include "model/bvh/node_format.h"
#include "model/bvh/two_level.h"
#include "traces/ray.h"

namespace rtsim {

constexpr uint32_t kXeBlockBytes = 64;          // ANV_RT_BLOCK_SIZE
constexpr uint32_t kXeNodeBytes = 64;           // ANV_RT_INTERNAL_NODE_SIZE
constexpr uint32_t kXeQuadBytes = 64;           // ANV_RT_QUAD_LEAF_SIZE
constexpr uint32_t kXeInstanceLeafBytes = 128;  // ANV_RT_INSTANCE_LEAF_SIZE
constexpr uint32_t kXeInstanceReadBytes = 64;   // instance_leaf_part0: what traversal reads
constexpr int kXeNodeSlots = 6;

// Node types (ANV_NODE_TYPE_*): a node whose children are all one leaf type takes that type (a
// "fat leaf"); otherwise it is mixed (0) and each child's type sits in its startPrim bits.
enum XeNodeType : uint8_t { kXeMixed = 0, kXeInstance = 1, kXeQuad = 4, kXeInvalid = 7 };

// The records as C structs, to pin their sizes and offsets to the driver's.
struct XeInternalNode {
  float lower[3];
  uint32_t child_block_offset;
  uint8_t node_type, reserved;
  int8_t exponent[3];
  uint8_t node_mask;
  uint8_t child_data[kXeNodeSlots];  // bits 0-1: blockIncr; bits 2-5: startPrim (child type)
  uint8_t lower_x[kXeNodeSlots], upper_x[kXeNodeSlots];
  uint8_t lower_y[kXeNodeSlots], upper_y[kXeNodeSlots];
  uint8_t lower_z[kXeNodeSlots], upper_z[kXeNodeSlots];
};
struct XeQuadLeaf {
  uint32_t shader_index_and_geom_mask, geometry_id_and_flags;
  uint32_t prim_index0, prim_index1_delta;
  float v[4][3];
};
struct XeInstanceLeafPart {  // part0 and part1 share this shape: 16 bytes, then four fp32 rows
  uint32_t dw0, dw1;         // part1: bvh_ptr (two words)
  uint64_t qw;               // part0: start node pointer and flags; part1: instance id, index
  float rows[4][3];          // part0: world2obj vx, vy, vz, obj2world p; part1: the converse
};

// Byte offsets in the 64-byte node (anv_internal_node).
constexpr size_t kXeChildOffset = offsetof(XeInternalNode, child_block_offset),
                 kXeType = offsetof(XeInternalNode, node_type),
                 kXeExponents = offsetof(XeInternalNode, exponent),
                 kXeMask = offsetof(XeInternalNode, node_mask),
                 kXeChildData = offsetof(XeInternalNode, child_data),
                 kXeLowerX = offsetof(XeInternalNode, lower_x);
constexpr uint32_t kXeQuadLastBit = 1u << 22;  // prim_index1_delta: last quad of the leaf

// One child of a node as the encoder places it: an inner node (1 block), a leaf of `blocks`
// quads, or an instance leaf (2 blocks).
struct XeChild {
  uint8_t type = kXeMixed;  // kXeMixed (an internal node), kXeQuad or kXeInstance
  uint8_t blocks = 1;       // blockIncr
};

// Writes a node whose children are stored from block `first_child` on, in the order of `order`
// (slots of `node`), each of child[slot].blocks blocks; `self` is the node's own block.
void encode_xe_node(const WideNode& node, const int order[kXeNodeSlots],
                    const XeChild child[kMaxWidth], uint32_t self, uint32_t first_child,
                    uint8_t* out);

// The grid step of an exponent byte, 2^(exponent - 8); the encoder keeps exponents in
// kXeMinExponent..127 so that the step is a normal float.
constexpr int kXeMinExponent = -118;
inline float xe_grid_step(int8_t exponent) {
  uint32_t bits = uint32_t(int(exponent) - 8 + 127) << 23;
  float step;
  std::memcpy(&step, &bits, 4);
  return step;
}

// Writes a quad of triangle `a` alone (second triangle off, as Mesa's encoder does), or of
// `a` and `b` when they share an edge and their ids differ by less than 2^16; returns false
// (writing nothing) for a pair that cannot share a quad. The last bit is set.
bool encode_xe_quad(const TriangleMesh& mesh, uint32_t a, const uint32_t* b, uint8_t* out);
// Sets or clears a written quad's "last quad in the leaf" bit.
void set_xe_quad_last(uint8_t* quad, bool last);

// Triangles of a quad (1 or 2) and the three corners of triangle k with its primitive id.
inline uint32_t xe_quad_triangles(const uint8_t* quad) {
  uint32_t delta;
  std::memcpy(&delta, quad + 12, 4);
  uint32_t j0 = (delta >> 16) & 3, j1 = (delta >> 18) & 3, j2 = (delta >> 20) & 3;
  return j0 == j1 && j1 == j2 ? 1 : 2;
}
inline uint32_t xe_quad_corners(const uint8_t* quad, uint32_t k, float vertices[9]) {
  uint32_t prim, delta;
  std::memcpy(&prim, quad + 8, 4);
  std::memcpy(&delta, quad + 12, 4);
  const uint8_t* v = quad + 16;
  for (uint32_t c = 0; c < 3; ++c) {
    uint32_t j = k == 0 ? c : (delta >> (16 + 2 * c)) & 3;
    std::memcpy(vertices + 3 * c, v + 12 * j, 12);
  }
  return k == 0 ? prim : prim + (delta & 0xffffu);
}

// The instance leaf: part0 and part1 from the record and its BLAS's root address.
void encode_xe_instance(const InstanceRecord& record, uint64_t blas_root, uint8_t* out);
// The root address an instance leaf points at, and setting it (part0's start node pointer and
// part1's BLAS pointer).
uint64_t xe_instance_root(const uint8_t* leaf);
void set_xe_instance_root(uint8_t* leaf, uint64_t root);
// What traversal reads of it (part0): the transform, mask and root address; the instance id
// comes from part1, which shading reads after the hit (the hardware reports the leaf).
InstanceRecord decode_xe_instance(const uint8_t* leaf, uint64_t& blas_root);

}  // namespace rtsim
