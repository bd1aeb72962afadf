#include "model/bvh/intel_nodes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/mat3x3.hpp>

#include "traces/alpha.h"

namespace rtsim {
namespace {

static_assert(sizeof(XeInternalNode) == kXeNodeBytes, "anv_internal_node is 64 bytes");
static_assert(sizeof(XeQuadLeaf) == kXeQuadBytes, "anv_quad_leaf_node is 64 bytes");
static_assert(2 * sizeof(XeInstanceLeafPart) == kXeInstanceLeafBytes,
              "anv_instance_leaf is 128 bytes");
static_assert(kXeChildOffset == 12 && kXeType == 16 && kXeExponents == 18 && kXeChildData == 22 &&
                  kXeLowerX == 28,
              "anv_internal_node field offsets");

// Geometry flags of a leaf descriptor (encode.comp): sub-type 0 in bits 24-27, opacity culling
// off (bit 29), opaque (bit 30).
constexpr uint32_t kDisableOpacityCull = 1u << 29, kOpaque = 1u << 30;

// Smallest exponent whose 255 grid steps from lo reach hi once rounded to fp32.
int8_t grid_exponent(float lo, float hi) {
  double length = double(hi) - double(lo);
  int e = kXeMinExponent;
  if (length > 0.0) e = std::clamp(std::ilogb(length / 255.0) + 8, kXeMinExponent, 127);
  while (e < 127 && cwbvh_plane(lo, xe_grid_step(int8_t(e)), 255) < hi) ++e;
  return int8_t(e);
}

void put32(uint8_t* out, uint32_t v) {
  std::memcpy(out, &v, 4);
}

uint32_t descriptor_flags(const TriangleMesh& mesh, uint32_t a, const uint32_t* b) {
  bool alpha = mesh.alpha && (mesh.alpha->tested(a) || (b && mesh.alpha->tested(*b)));
  return kDisableOpacityCull | (alpha ? 0 : kOpaque);
}

}  // namespace

void encode_xe_node(const WideNode& node, const int order[kXeNodeSlots],
                    const XeChild child[kMaxWidth], uint32_t self, uint32_t first_child,
                    uint8_t* out) {
  if (node.child_count > kXeNodeSlots) throw std::logic_error("xe6: more than 6 children");
  std::memset(out, 0, kXeNodeBytes);
  std::memcpy(out, &node.box.lo, 12);
  put32(out + kXeChildOffset, first_child - self);
  float step[3];
  for (int axis = 0; axis < 3; ++axis) {
    auto e = grid_exponent(node.box.lo[axis], node.box.hi[axis]);
    out[kXeExponents + axis] = uint8_t(e);
    step[axis] = xe_grid_step(e);
  }
  // A fat leaf when every child is a leaf of one type; otherwise mixed, types per child.
  uint8_t type = child[order[0]].type;
  for (int i = 1; i < node.child_count; ++i)
    if (child[order[i]].type != type) type = kXeMixed;
  out[kXeType] = type;
  out[kXeMask] = 0xff;
  for (int i = 0; i < kXeNodeSlots; ++i) {
    if (i >= node.child_count) {  // empty: lower_x 0x80, upper_x 0; type invalid
      out[kXeLowerX + i] = 0x80;
      out[kXeChildData + i] = uint8_t(kXeInvalid << 2);
      continue;
    }
    const XeChild& c = child[order[i]];
    out[kXeChildData + i] = uint8_t(c.blocks | (type == kXeMixed ? c.type << 2 : 0));
    const Bounds& box = node.child[order[i]].box;
    for (int axis = 0; axis < 3; ++axis) {
      uint8_t* planes = out + kXeLowerX + 12 * axis;
      planes[i] = quantize_down(node.box.lo[axis], step[axis], box.lo[axis]);
      planes[kXeNodeSlots + i] = quantize_up(node.box.lo[axis], step[axis], box.hi[axis]);
    }
  }
}

void decode_xe6(const uint8_t* bytes, uint32_t self, NodeView& view) {
  view.slots = kXeNodeSlots;
  view.valid = 0;
  float origin[3];
  std::memcpy(origin, bytes, 12);
  uint32_t next;
  std::memcpy(&next, bytes + kXeChildOffset, 4);
  next += self;
  uint8_t type = bytes[kXeType];
  for (int axis = 0; axis < 3; ++axis) {
    float scale = xe_grid_step(int8_t(bytes[kXeExponents + axis]));
    const uint8_t* lo = bytes + kXeLowerX + 12 * axis;
    float* lo_out = view.planes[2 * axis];
    float* hi_out = view.planes[2 * axis + 1];
    for (int s = 0; s < kXeNodeSlots; ++s) {
      lo_out[s] = origin[axis] + static_cast<float>(lo[s]) * scale;
      hi_out[s] = origin[axis] + static_cast<float>(lo[kXeNodeSlots + s]) * scale;
    }
    view.lo[axis] = lo_out;
    view.hi[axis] = hi_out;
  }
  const uint8_t* upper_x = bytes + kXeLowerX + kXeNodeSlots;
  for (int s = 0; s < kXeNodeSlots; ++s) {
    uint8_t data = bytes[kXeChildData + s];
    bool valid = !(bytes[kXeLowerX + s] & 0x80) || (upper_x[s] & 0x80);
    if (!valid) continue;
    uint8_t child_type = type == kXeMixed ? uint8_t((data >> 2) & 15) : type;
    uint32_t blocks = data & 3u;
    view.valid |= 1u << s;
    view.index[s] = next;
    view.count[s] = child_type == kXeMixed ? 0 : child_type == kXeQuad ? blocks : 1;
    next += blocks;
  }
}

bool encode_xe_quad(const TriangleMesh& mesh, uint32_t a, const uint32_t* b, uint8_t* out) {
  uint32_t first = a, second = b ? *b : a;
  if (b && second < first) std::swap(first, second);
  std::array<glm::vec3, 3> va = mesh.corners(first);
  glm::vec3 v[4] = {va[0], va[1], va[2], glm::vec3(0.0f)};
  uint32_t delta = 0;
  if (b) {
    // The second triangle's corners as indices into the four vertices, in its own order.
    std::array<glm::vec3, 3> vb = mesh.corners(second);
    uint32_t shared = 0, j[3];
    bool fourth = false;
    for (int c = 0; c < 3; ++c) {
      auto at = std::find(va.begin(), va.end(), vb[c]);
      if (at != va.end()) {
        j[c] = uint32_t(at - va.begin());
        shared++;
      } else {
        j[c] = 3;
        v[3] = vb[c];
        fourth = true;
      }
    }
    if (shared != 2 || !fourth || second - first > 0xffffu) return false;
    delta = (second - first) | j[0] << 16 | j[1] << 18 | j[2] << 20;
  }
  std::memset(out, 0, kXeQuadBytes);
  uint32_t flags = descriptor_flags(mesh, a, b);
  put32(out, 0xff000000u);  // shader index 0, geometry mask 0xff
  put32(out + 4, flags);
  put32(out + 8, first);
  put32(out + 12, delta | kXeQuadLastBit);
  std::memcpy(out + 16, v, 48);
  return true;
}

void set_xe_quad_last(uint8_t* quad, bool last) {
  uint32_t delta;
  std::memcpy(&delta, quad + 12, 4);
  put32(quad + 12, last ? delta | kXeQuadLastBit : delta & ~kXeQuadLastBit);
}

void encode_xe_instance(const InstanceRecord& r, uint64_t blas_root, uint8_t* out) {
  std::memset(out, 0, kXeInstanceLeafBytes);
  put32(out, uint32_t(r.mask) << 24);  // shader index 0, geometry mask
  put32(out + 4, kDisableOpacityCull);
  uint64_t start = blas_root & ((uint64_t(1) << 48) - 1);  // instance flags (bits 48-55) 0
  std::memcpy(out + 8, &start, 8);
  // part0: world-to-object 3x3 by columns, then the object-to-world translation.
  for (int c = 0; c < 3; ++c) std::memcpy(out + 16 + 12 * c, &r.to_object.linear[c], 12);
  std::memcpy(out + 52, &r.to_world.offset, 12);
  // part1: BLAS pointer, instance id and index, object-to-world 3x3, world-to-object offset.
  std::memcpy(out + 64, &start, 8);
  put32(out + 72, r.instance);
  put32(out + 76, r.instance);
  for (int c = 0; c < 3; ++c) std::memcpy(out + 80 + 12 * c, &r.to_world.linear[c], 12);
  std::memcpy(out + 116, &r.to_object.offset, 12);
}

uint64_t xe_instance_root(const uint8_t* leaf) {
  uint64_t root;
  std::memcpy(&root, leaf + 8, 8);
  return root & ((uint64_t(1) << 48) - 1);
}

void set_xe_instance_root(uint8_t* leaf, uint64_t root) {
  uint64_t start = root & ((uint64_t(1) << 48) - 1);
  std::memcpy(leaf + 8, &start, 8);
  std::memcpy(leaf + 64, &start, 8);
}

InstanceRecord decode_xe_instance(const uint8_t* leaf, uint64_t& blas_root) {
  InstanceRecord r;
  r.mask = leaf[3];
  std::memcpy(&blas_root, leaf + 8, 8);
  blas_root &= (uint64_t(1) << 48) - 1;
  for (int c = 0; c < 3; ++c) std::memcpy(&r.to_object.linear[c], leaf + 16 + 12 * c, 12);
  std::memcpy(&r.to_world.offset, leaf + 52, 12);
  // The hardware moves the origin by -p before the 3x3; the same map as one affine transform,
  // its offset -(M p) rounded once.
  glm::dvec3 offset = glm::dmat3(r.to_object.linear) * glm::dvec3(r.to_world.offset);
  r.to_object.offset = glm::vec3(-offset);
  std::memcpy(&r.instance, leaf + 76, 4);  // part1: the hit reports the leaf; shading reads it
  return r;
}

}  // namespace rtsim
