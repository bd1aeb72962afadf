#include "model/bvh/node_format.h"

#include "model/bvh/amd_nodes.h"
#include "model/bvh/intel_nodes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rtsim {
namespace {

void put32(uint8_t* out, uint32_t v) {
  std::memcpy(out, &v, 4);
}

// Smallest exponent byte whose 255 steps from lo reach hi once rounded to fp32.
uint8_t grid_exponent(float lo, float hi) {
  int e = 1;
  double steps = (double(hi) - double(lo)) / 255.0;
  if (steps > 0.0) e = std::clamp(std::ilogb(steps) + 127, 1, 254);
  while (e < 254 && cwbvh_plane(lo, cwbvh_scale(uint8_t(e)), 255) < hi) ++e;
  return uint8_t(e);
}

void encode_aabb32(int width, const WideNode& node, const ChildPlacement& placement, uint8_t* out) {
  std::memset(out, 0, node_stride(NodeFormat::Aabb32, width));
  for (int c = 0; c < node.child_count; ++c) {
    const WideChild& child = node.child[c];
    for (int axis = 0; axis < 3; ++axis) {
      std::memcpy(out + 4 * ((2 * axis) * width + c), &child.box.lo[axis], 4);
      std::memcpy(out + 4 * ((2 * axis + 1) * width + c), &child.box.hi[axis], 4);
    }
    put32(out + 24 * width + 4 * c, placement.position[c]);
    out[28 * width + c] = child.leaf() ? uint8_t(child.count) : kAabbInnerCount;
  }
}

void encode_cwbvh8(const WideNode& node, const ChildPlacement& placement, uint8_t* out) {
  std::memset(out, 0, kCwbvhNodeBytes);
  std::memcpy(out + kCwbvhOrigin, &node.box.lo, 12);
  float scale[3];
  for (int axis = 0; axis < 3; ++axis) {
    out[kCwbvhExponents + axis] = grid_exponent(node.box.lo[axis], node.box.hi[axis]);
    scale[axis] = cwbvh_scale(out[kCwbvhExponents + axis]);
  }
  // Children: inner ones must sit side by side from the first, triangles likewise.
  uint32_t child_base = 0, tri_base = 0, inner_seen = 0, tri_seen = 0;
  bool any_inner = false, any_leaf = false;
  uint8_t imask = 0;
  for (int c = 0; c < node.child_count; ++c) {
    const WideChild& child = node.child[c];
    uint32_t pos = placement.position[c];
    if (child.leaf()) {
      if (!any_leaf) tri_base = pos;
      any_leaf = true;
      uint32_t offset = pos - tri_base;
      if (pos < tri_base || offset != tri_seen || offset > 23 || child.count > 3)
        throw std::logic_error("cwbvh8: leaf triangles are not contiguous");
      tri_seen += child.count;
      out[kCwbvhMeta + c] = uint8_t((((1u << child.count) - 1) << 5) | offset);
    } else {
      if (!any_inner) child_base = pos;
      any_inner = true;
      if (pos != child_base + inner_seen)
        throw std::logic_error("cwbvh8: sibling nodes are not contiguous");
      inner_seen++;
      imask |= uint8_t(1u << c);
      out[kCwbvhMeta + c] = uint8_t((1u << 5) | (24 + c));
    }
    for (int axis = 0; axis < 3; ++axis) {
      out[kCwbvhQuantLo + 8 * axis + c] =
          quantize_down(node.box.lo[axis], scale[axis], child.box.lo[axis]);
      out[kCwbvhQuantHi + 8 * axis + c] =
          quantize_up(node.box.lo[axis], scale[axis], child.box.hi[axis]);
    }
  }
  out[kCwbvhInnerMask] = imask;
  put32(out + kCwbvhChildBase, child_base);
  put32(out + kCwbvhTriBase, tri_base);
}

}  // namespace

uint8_t quantize_down(float origin, float scale, float value) {
  double q = std::floor((double(value) - double(origin)) / double(scale));
  int qi = static_cast<int>(std::clamp(q, 0.0, 255.0));
  while (qi > 0 && cwbvh_plane(origin, scale, uint8_t(qi)) > value) --qi;
  return uint8_t(qi);
}

// Smallest q whose decoded plane is >= value.
uint8_t quantize_up(float origin, float scale, float value) {
  double q = std::ceil((double(value) - double(origin)) / double(scale));
  int qi = static_cast<int>(std::clamp(q, 0.0, 255.0));
  while (qi < 255 && cwbvh_plane(origin, scale, uint8_t(qi)) < value) ++qi;
  return uint8_t(qi);
}

uint32_t node_stride(NodeFormat format, int width) {
  switch (format) {
    case NodeFormat::Cwbvh8: return kCwbvhNodeBytes;
    case NodeFormat::AmdBox32: return kAmdBox32Bytes;
    case NodeFormat::AmdBox16: return kAmdBox16Bytes;
    case NodeFormat::Xe6: return kXeNodeBytes;
    default: return (29u * width + 63u) / 64u * 64u;
  }
}

void encode_node(NodeFormat format, int width, const WideNode& node,
                 const ChildPlacement& placement, uint8_t* out, const RecordRegions& regions) {
  if (format == NodeFormat::Xe6)
    throw std::logic_error("xe6 nodes are placed with their leaves (place_xe_blocks)");
  if (format == NodeFormat::Cwbvh8)
    encode_cwbvh8(node, placement, out);
  else if (format == NodeFormat::Aabb32)
    encode_aabb32(width, node, placement, out);
  else
    encode_amd_box(format == NodeFormat::AmdBox16, node, placement, regions, out);
}

}  // namespace rtsim
