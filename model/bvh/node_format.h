// Byte layouts of BVH nodes in the simulated memory (see model/README.md for the tables):
//  - aabb32: fp32 child boxes in SoA order, a 32-bit reference and an 8-bit count per child;
//    29 bytes per child slot, rounded up to whole 64-byte lines (BVH8: 256 B).
//  - cwbvh8: the compressed wide node of Ylitie, Karras & Laine, "Efficient Incoherent Ray
//    Traversal on GPUs Through Compressed Wide BVHs" (HPG 2017): 80 bytes, 8 slots, child boxes
//    quantized to 8 bits per plane on a per-node power-of-two grid, rounded outward so the
//    decoded fp32 box always contains the exact one.
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

// Writes one node. For cwbvh8 the caller guarantees sibling and triangle contiguity; it throws
// std::logic_error if they do not hold.
void encode_node(NodeFormat format, int width, const WideNode& node,
                 const ChildPlacement& placement, uint8_t* out);

// One decoded node: child boxes (fp32, conservative), references and counts.
struct NodeView {
  int slots = 0;           // child slots of the format
  uint32_t valid = 0;      // bit s: slot s holds a child
  float lo[3][kMaxWidth];  // per axis, per slot
  float hi[3][kMaxWidth];
  uint32_t index[kMaxWidth];  // inner: node position; leaf: first triangle position
  uint32_t count[kMaxWidth];  // leaf: triangles; 0 for an inner child
};

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

void decode_aabb32(const uint8_t* bytes, int width, NodeView& view);
void decode_cwbvh8(const uint8_t* bytes, NodeView& view);

inline void decode_node(NodeFormat format, int width, const uint8_t* bytes, NodeView& view) {
  if (format == NodeFormat::Cwbvh8)
    decode_cwbvh8(bytes, view);
  else
    decode_aabb32(bytes, width, view);
}

}  // namespace rtsim
