#include "model/bvh/amd_instances.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "model/bvh/amd_nodes.h"

namespace rtsim {
namespace {

constexpr size_t kBvhPtr = 0, kCustomAndMask = 8, kWorldToObject = 16, kInstanceId = 64,
                 kObjectToWorld = 80;
constexpr uint64_t kNodeAddressMask = (uint64_t(1) << 45) - 1;

// radv's addr_to_node (src/amd/vulkan/bvh/build_helpers.h).
uint64_t addr_to_node(uint64_t address) {
  return (address >> 3) & kNodeAddressMask;
}

// mat3x4 rows: (linear row, offset) for rows x, y, z.
void put_rows(const Transform& t, uint8_t* out) {
  float rows[12];
  for (int row = 0; row < 3; ++row) {
    for (int c = 0; c < 3; ++c) rows[4 * row + c] = t.linear[c][row];
    rows[4 * row + 3] = t.offset[row];
  }
  std::memcpy(out, rows, sizeof rows);
}

Transform get_rows(const uint8_t* in) {
  float rows[12];
  std::memcpy(rows, in, sizeof rows);
  Transform t;
  for (int row = 0; row < 3; ++row) {
    for (int c = 0; c < 3; ++c) t.linear[c][row] = rows[4 * row + c];
    t.offset[row] = rows[4 * row + 3];
  }
  return t;
}

}  // namespace

void encode_amd_instance(const InstanceRecord& r, uint8_t* out) {
  std::memset(out, 0, kAmdInstanceBytes);
  uint64_t blas = r.blas;
  std::memcpy(out + kBvhPtr, &blas, 8);
  uint32_t custom_and_mask = (r.instance & 0xffffffu) | (uint32_t(r.mask) << 24);
  std::memcpy(out + kCustomAndMask, &custom_and_mask, 4);
  put_rows(r.to_object, out + kWorldToObject);
  std::memcpy(out + kInstanceId, &r.instance, 4);
  put_rows(r.to_world, out + kObjectToWorld);
}

void link_amd_instances(BvhImage& top, const std::vector<BvhImage>& bottom) {
  for (uint32_t p = 0; p < top.triangle_count; ++p) {
    uint8_t* node = top.triangles.data() + size_t(p) * top.triangle_stride;
    uint64_t blas;
    std::memcpy(&blas, node + kBvhPtr, 8);
    uint64_t pointer = addr_to_node(bottom.at(blas).node_base);
    std::memcpy(node + kBvhPtr, &pointer, 8);
  }
}

InstanceRecord read_amd_instance(const uint8_t* in, const std::vector<BvhImage>& bottom) {
  InstanceRecord r;
  uint64_t pointer;
  std::memcpy(&pointer, in + kBvhPtr, 8);
  uint64_t root = pointer << 3;
  auto blas = std::lower_bound(bottom.begin(), bottom.end(), root,
                               [](const BvhImage& b, uint64_t a) { return b.node_base < a; });
  if (blas == bottom.end() || blas->node_base != root)
    throw std::logic_error("amd instance node: bvh_ptr names no bottom level");
  r.blas = uint32_t(blas - bottom.begin());
  uint32_t custom_and_mask;
  std::memcpy(&custom_and_mask, in + kCustomAndMask, 4);
  r.mask = uint8_t(custom_and_mask >> 24);
  r.to_object = get_rows(in + kWorldToObject);
  std::memcpy(&r.instance, in + kInstanceId, 4);
  r.to_world = get_rows(in + kObjectToWorld);
  return r;
}

}  // namespace rtsim
