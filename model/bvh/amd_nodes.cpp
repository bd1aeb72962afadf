#include "model/bvh/amd_nodes.h"

#include <cmath>
#include <limits>

#include <fmt/core.h>

#include "model/bvh/bvh_image.h"
#include "model/bvh/node_format.h"
#include "traces/error.h"

namespace rtsim {
namespace {

constexpr uint16_t kHalfMaxMagnitude = 0x7bff;  // 65504
constexpr uint16_t kHalfInfMagnitude = 0x7c00;

void put32(uint8_t* out, uint32_t v) {
  std::memcpy(out, &v, 4);
}

// The half nearest zero whose magnitude is not above |value|'s (value finite or infinite).
uint16_t half_toward_zero(float value) {
  uint32_t bits;
  std::memcpy(&bits, &value, 4);
  uint16_t sign = uint16_t((bits >> 16) & 0x8000u);
  float magnitude = std::fabs(value);
  uint16_t h;
  if (std::isinf(magnitude))
    h = kHalfInfMagnitude;
  else if (magnitude > 65504.0f)
    h = kHalfMaxMagnitude;
  else if (magnitude < 0x1p-14f)  // subnormal half: steps of 2^-24 (exact scaling)
    h = uint16_t(magnitude * 0x1p24f);
  else  // normal: rebias the exponent, keep the top 10 mantissa bits
    h = uint16_t(((((bits >> 23) & 0xffu) - 127u + 15u) << 10) | ((bits >> 13) & 0x3ffu));
  return uint16_t(sign | h);
}

// The next half away from zero (a magnitude step; the largest finite steps to infinity).
uint16_t half_away(uint16_t h) {
  return (h & 0x7fffu) >= kHalfInfMagnitude ? h : uint16_t(h + 1);
}

}  // namespace

float half_to_float(uint16_t h) {
  uint32_t sign = uint32_t(h & 0x8000u) << 16, exponent = (h >> 10) & 0x1fu, mantissa = h & 0x3ffu;
  float magnitude;
  if (exponent == 0) {
    magnitude = float(mantissa) * 0x1p-24f;
  } else if (exponent == 31) {
    magnitude =
        mantissa ? std::numeric_limits<float>::quiet_NaN() : std::numeric_limits<float>::infinity();
  } else {
    uint32_t bits = ((exponent - 15u + 127u) << 23) | (mantissa << 13);
    std::memcpy(&magnitude, &bits, 4);
  }
  uint32_t bits;
  std::memcpy(&bits, &magnitude, 4);
  bits |= sign;
  float out;
  std::memcpy(&out, &bits, 4);
  return out;
}

uint16_t half_round_down(float value) {
  uint16_t h = half_toward_zero(value);
  // Toward zero is down for a positive value; a negative one may need one step further down.
  if (value < 0.0f && half_to_float(h) > value) h = half_away(h);
  return h;
}

uint16_t half_round_up(float value) {
  uint16_t h = half_toward_zero(value);
  if (value > 0.0f && half_to_float(h) < value) h = half_away(h);
  return h;
}

uint32_t amd_node_id(uint64_t offset, uint32_t type) {
  if (offset > 0xffffffc0u)
    throw_input_error("bvh", "",
                      fmt::format("a record lies {} bytes from the level's first node: AMD node "
                                  "ids reach 4 GiB (radv's 32-bit id_to_offset); use a smaller "
                                  "scene",
                                  offset));
  return uint32_t(offset >> 3) | type;
}

void encode_amd_box(bool fp16, const WideNode& node, const ChildPlacement& placement,
                    const RecordRegions& regions, uint8_t* out) {
  std::memset(out, 0, fp16 ? kAmdBox16Bytes : kAmdBox32Bytes);
  uint32_t leaf_type = regions.instance_leaves ? kAmdTypeInstance : kAmdTypeTriangle;
  uint32_t node_type = fp16 ? kAmdTypeBox16 : kAmdTypeBox32;
  for (int c = 0; c < kAmdBoxSlots; ++c) {
    uint32_t id = kAmdInvalidNode;
    if (c < node.child_count) {
      const WideChild& child = node.child[c];
      uint64_t position = placement.position[c];
      id = child.leaf()
               ? amd_node_id(regions.leaf_offset + position * regions.leaf_stride, leaf_type)
               : amd_node_id(position * regions.node_stride, node_type);
    }
    put32(out + 4 * c, id);
    // radv writes NaN planes for an empty slot (encode.comp).
    float lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      bool used = c < node.child_count;
      lo[a] = used ? node.child[c].box.lo[a] : std::numeric_limits<float>::quiet_NaN();
      hi[a] = used ? node.child[c].box.hi[a] : std::numeric_limits<float>::quiet_NaN();
    }
    if (fp16) {
      uint16_t planes[6];
      for (int a = 0; a < 3; ++a) {
        planes[a] = half_round_down(lo[a]);
        planes[3 + a] = half_round_up(hi[a]);
      }
      std::memcpy(out + kAmdBoxCoords + 12 * c, planes, 12);
    } else {
      std::memcpy(out + kAmdBoxCoords + 24 * c, lo, 12);
      std::memcpy(out + kAmdBoxCoords + 24 * c + 12, hi, 12);
    }
  }
  // box32 flags: written by set_amd_box_flags() once the leaf records exist; box16 has none.
}

void set_amd_box_flags(BvhImage& image) {
  if (image.config.node_format != NodeFormat::AmdBox32) return;
  uint64_t leaf_offset = image.triangle_base - image.node_base;
  for (uint32_t n = 0; n < image.node_count; ++n) {
    uint8_t* node = image.nodes.data() + size_t(n) * image.node_stride;
    uint32_t flags = 0;
    for (int c = 0; c < kAmdBoxSlots; ++c) {
      uint32_t id;
      std::memcpy(&id, node + 4 * c, 4);
      if (id == kAmdInvalidNode || (id & 7u) != kAmdTypeTriangle) continue;
      uint64_t position = ((uint64_t(id) << 3) - leaf_offset) / image.triangle_stride;
      uint32_t geometry;
      std::memcpy(&geometry, image.triangle_bytes(uint32_t(position)) + kAmdTriangleGeometry, 4);
      flags |= ((geometry & kAmdGeometryOpaque) ? kAmdBoxOnlyOpaque : kAmdBoxNoOpaque) << (8 * c);
    }
    put32(node + kAmdBox32Flags, flags);
  }
}

void decode_amd_box(bool fp16, const uint8_t* bytes, const RecordRegions& regions, NodeView& view) {
  view.slots = kAmdBoxSlots;
  view.valid = 0;
  uint32_t ids[kAmdBoxSlots];
  std::memcpy(ids, bytes, sizeof ids);
  for (int s = 0; s < kAmdBoxSlots; ++s) {
    float planes[6];
    if (fp16) {
      uint16_t halves[6];
      std::memcpy(halves, bytes + kAmdBoxCoords + 12 * s, 12);
      for (int p = 0; p < 6; ++p) planes[p] = half_to_float(halves[p]);
    } else {
      std::memcpy(planes, bytes + kAmdBoxCoords + 24 * s, 24);
    }
    for (int a = 0; a < 3; ++a) {
      view.planes[2 * a][s] = planes[a];
      view.planes[2 * a + 1][s] = planes[3 + a];
    }
    if (ids[s] == kAmdInvalidNode) continue;
    view.valid |= 1u << s;
    // id_to_offset: the low 3 bits are the type, the rest the offset in 8-byte units.
    uint64_t offset = uint64_t(ids[s] & ~7u) << 3;
    uint32_t type = ids[s] & 7u;
    bool leaf = type == kAmdTypeTriangle || type == kAmdTypeInstance;
    view.index[s] = leaf ? uint32_t((offset - regions.leaf_offset) / regions.leaf_stride)
                         : uint32_t(offset / regions.node_stride);
    view.count[s] = leaf ? 1 : 0;
  }
  for (int a = 0; a < 3; ++a) {
    view.lo[a] = view.planes[2 * a];
    view.hi[a] = view.planes[2 * a + 1];
  }
}

void encode_amd_triangle(const float vertices[9], uint32_t prim, bool opaque, uint8_t* out) {
  std::memset(out, 0, kAmdTriangleBytes);
  std::memcpy(out, vertices, 36);
  put32(out + kAmdTriangleId, prim);
  put32(out + kAmdTriangleGeometry, opaque ? kAmdGeometryOpaque : 0u);  // geometry 0
  put32(out + kAmdTriangleControl, kAmdBarycentricsControl);
}

}  // namespace rtsim
