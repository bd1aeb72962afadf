// Byte layouts of BVH nodes in the simulated memory (see model/README.md for the tables):
//  - aabb32: fp32 child boxes in SoA order, a 32-bit reference and an 8-bit count per child;
//    29 bytes per child slot, rounded up to whole 64-byte lines (BVH8: 256 B).
//  - cwbvh8: the compressed wide node of Ylitie, Karras & Laine, "Efficient Incoherent Ray
//    Traversal on GPUs Through Compressed Wide BVHs" (HPG 2017): 80 bytes, 8 slots, child boxes
//    quantized to 8 bits per plane on a per-node power-of-two grid, rounded outward so the
//    decoded fp32 box always contains the exact one.
//  - amd_box32, amd_box16: AMD RDNA2/3's 4-wide nodes as Mesa's radv writes them (amd_nodes.h).
//  - xe6: Intel's 64-byte 6-wide node (model/bvh/intel_nodes.h), children in 64-byte blocks
//    relative to the node's own position.
// decode_node() is what the hardware's node decoder computes; it feeds the ray-box unit.
#pragma once

#include <cstdint>
#include <cstring>

#include "model/bvh/bvh_config.h"
#include "model/bvh/wide_bvh.h"

namespace rtsim {

constexpr uint32_t kCwbvhNodeBytes = 80;
constexpr uint8_t kAabbInnerCount = 255;  // aabb32 count byte of an inner child; 0 = empty

// Bytes of one node in the format at the given width.
uint32_t node_stride(NodeFormat format, int width);

// Where each child of a node went in memory: inner children by node position, leaves by the
// position of their first triangle.
struct ChildPlacement {
  uint32_t position[kMaxWidth] = {};
};

// Where a level's records lie, for formats whose children are byte offsets from the level's
// first node (amd_box32, amd_box16: amd_nodes.h); aabb32 and cwbvh8 ignore it.
struct RecordRegions {
  uint32_t node_stride = 0;      // bytes per node record
  uint32_t leaf_stride = 0;      // bytes per leaf record
  uint64_t leaf_offset = 0;      // bytes from the first node to the first leaf record
  bool instance_leaves = false;  // the leaf records are instance records (a top level)
};

// Writes one node. For cwbvh8 the caller guarantees sibling and triangle contiguity; it throws
// std::logic_error if they do not hold.
void encode_node(NodeFormat format, int width, const WideNode& node,
                 const ChildPlacement& placement, uint8_t* out, const RecordRegions& regions = {});

// A float that may alias the node bytes it is read from.
using AliasedFloat = float __attribute__((__may_alias__));

// One decoded node: child boxes (fp32, conservative), references and counts. lo and hi point at
// kMaxWidth planes per axis, in the node's own bytes (aabb32, width 8) or in `planes`.
struct NodeView {
  int slots = 0;                   // child slots of the format
  uint32_t valid = 0;              // bit s: slot s holds a child
  const AliasedFloat* lo[3] = {};  // per axis: kMaxWidth lower planes
  const AliasedFloat* hi[3] = {};  // per axis: kMaxWidth upper planes
  uint32_t index[kMaxWidth];       // inner: node position; leaf: first triangle position
  uint32_t count[kMaxWidth];       // leaf: triangles; 0 for an inner child
  float planes[6][kMaxWidth];      // decoded planes: lo x, hi x, lo y, hi y, lo z, hi z
};

// Set bits of an 8-bit mask (portable: no popcount instruction assumed).
inline uint32_t count_bits(uint32_t mask) {
  mask = mask - ((mask >> 1) & 0x55u);
  mask = (mask & 0x33u) + ((mask >> 2) & 0x33u);
  return (mask + (mask >> 4)) & 0x0fu;
}

// Largest q whose decoded plane (origin + q * scale) is <= value, and smallest whose is >= value:
// the box grows outward, never inward (cwbvh8 and xe6).
uint8_t quantize_down(float origin, float scale, float value);
uint8_t quantize_up(float origin, float scale, float value);

// Decodes an xe6 node at block position `self` (model/bvh/intel_nodes.cpp): count[s] is a leaf
// child's quads (1 for an instance leaf), index[s] its first block.
void decode_xe6(const uint8_t* bytes, uint32_t self, NodeView& view);

// Quantized-box arithmetic of cwbvh8, shared by the encoder and the decoder so the outward
// rounding holds for the decoded value exactly as the hardware computes it.
inline float cwbvh_scale(uint8_t exponent_byte) {
  uint32_t bits = uint32_t(exponent_byte) << 23;
  float scale;
  std::memcpy(&scale, &bits, 4);
  return scale;
}
inline float cwbvh_plane(float origin, float scale, uint8_t q) {
  return origin + static_cast<float>(q) * scale;
}

// cwbvh8 byte offsets (table in model/README.md).
constexpr size_t kCwbvhOrigin = 0, kCwbvhExponents = 12, kCwbvhInnerMask = 15, kCwbvhChildBase = 16,
                 kCwbvhTriBase = 20, kCwbvhMeta = 24, kCwbvhQuantLo = 32, kCwbvhQuantHi = 56;

inline void decode_aabb32(const uint8_t* bytes, int width, NodeView& view) {
  view.slots = width;
  view.valid = 0;
  for (int plane = 0; plane < 6; ++plane) {
    const uint8_t* source = bytes + 4 * plane * width;
    // Width 8 planes are read in place; narrower nodes are copied to whole rows.
    if (width != kMaxWidth) std::memcpy(view.planes[plane], source, 4 * width);
    const AliasedFloat* row =
        width == kMaxWidth ? reinterpret_cast<const AliasedFloat*>(source) : view.planes[plane];
    (plane % 2 ? view.hi : view.lo)[plane / 2] = row;
  }
  std::memcpy(view.index, bytes + 24 * width, 4 * width);
  const uint8_t* counts = bytes + 28 * width;
  for (int s = 0; s < width; ++s) {
    view.valid |= uint32_t(counts[s] != 0) << s;
    view.count[s] = counts[s] == kAabbInnerCount ? 0 : counts[s];
  }
}

inline void decode_cwbvh8(const uint8_t* bytes, NodeView& view) {
  view.slots = 8;
  view.valid = 0;
  float origin[3];
  std::memcpy(origin, bytes + kCwbvhOrigin, 12);
  uint8_t imask = bytes[kCwbvhInnerMask];
  uint32_t child_base, tri_base;
  std::memcpy(&child_base, bytes + kCwbvhChildBase, 4);
  std::memcpy(&tri_base, bytes + kCwbvhTriBase, 4);
  // Planes: origin + q * 2^e per axis, exactly as the encoder rounded them.
  for (int plane = 0; plane < 6; ++plane) {
    int axis = plane / 2;
    const uint8_t* q = bytes + (plane % 2 ? kCwbvhQuantHi : kCwbvhQuantLo) + 8 * axis;
    float base = origin[axis], scale = cwbvh_scale(bytes[kCwbvhExponents + axis]);
    float* out = view.planes[plane];
    for (int s = 0; s < 8; ++s) out[s] = base + static_cast<float>(q[s]) * scale;
    (plane % 2 ? view.hi : view.lo)[axis] = out;
  }
  // References: inner children by rank among inner slots, leaves by their triangle offset.
  for (int s = 0; s < 8; ++s) {
    uint8_t meta = bytes[kCwbvhMeta + s];
    if (meta == 0) continue;
    view.valid |= 1u << s;
    if (imask & (1u << s)) {
      view.index[s] = child_base + count_bits(imask & ((1u << s) - 1));
      view.count[s] = 0;
    } else {
      view.index[s] = tri_base + (meta & 31u);
      view.count[s] = count_bits(meta >> 5);
    }
  }
}

// amd_box32 and amd_box16 (amd_nodes.cpp): child ids back to positions through `regions`.
void decode_amd_box(bool fp16, const uint8_t* bytes, const RecordRegions& regions, NodeView& view);

// position: the node's own position (xe6 children are relative to it); regions: where the
// records lie (amd formats' children are byte offsets).
inline void decode_node(NodeFormat format, int width, const uint8_t* bytes, NodeView& view,
                        uint32_t position, const RecordRegions& regions = {}) {
  if (format == NodeFormat::Cwbvh8)
    decode_cwbvh8(bytes, view);
  else if (format == NodeFormat::Xe6)
    decode_xe6(bytes, position, view);
  else if (format == NodeFormat::Aabb32)
    decode_aabb32(bytes, width, view);
  else
    decode_amd_box(format == NodeFormat::AmdBox16, bytes, regions, view);
}

}  // namespace rtsim
