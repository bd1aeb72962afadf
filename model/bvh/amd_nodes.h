// AMD RDNA2/RDNA3 BVH records, byte for byte as Mesa's radv driver writes them
// (src/amd/vulkan/bvh/bvh.h; sizes asserted in radv_GetAccelerationStructureBuildSizesKHR,
// src/amd/vulkan/radv_acceleration_structure.c; writers in src/amd/vulkan/bvh/encode.comp and
// encode.h). Tables in model/README.md, "AMD formats".
//  - amd_box32: struct radv_bvh_box32_node, 128 B: u32 children[4], vk_aabb coords[4] (fp32
//    min xyz then max xyz per child), u32 flags, u32 reserved[3].
//  - amd_box16: struct radv_bvh_box16_node, 64 B: u32 children[4], float16 coords[4][2][3],
//    each plane rounded outward (min down, max up) so the decoded box contains the exact one.
//  - amd_tri: struct radv_bvh_triangle_node, 64 B: float coords[3][3], u32 reserved[3],
//    triangle_id, geometry_id_and_flags (bit 31: opaque), reserved2, id (barycentrics
//    control, 9 as radv_encode_triangle_gfx10_3 writes it).
//  - instance: struct radv_bvh_instance_node, 128 B (amd_instance_* in two_level.h).
// A child is a node id (radv's pack_node_id, build_helpers.h): the child's byte offset from the
// level's first node, shifted right by 3, OR'd with its type in the low 3 bits (triangle 0,
// box16 4, box32 5, instance 6); 0xffffffff is an empty slot. The decoder turns ids back into
// node and leaf-record positions; it feeds the same ray-box unit as the other formats.
#pragma once

#include <cstdint>
#include <cstring>

#include "model/bvh/wide_bvh.h"

namespace rtsim {

struct BvhImage;
struct NodeView;
struct ChildPlacement;
struct RecordRegions;

constexpr uint32_t kAmdBox32Bytes = 128;     // sizeof(radv_bvh_box32_node)
constexpr uint32_t kAmdBox16Bytes = 64;      // sizeof(radv_bvh_box16_node)
constexpr uint32_t kAmdTriangleBytes = 64;   // sizeof(radv_bvh_triangle_node)
constexpr uint32_t kAmdInstanceBytes = 128;  // sizeof(radv_bvh_instance_node)
// What radv's traversal loop reads of an instance node: bvh_ptr, custom_instance_and_mask,
// sbt_offset_and_flags and wto_matrix (radv_rt_common.c, radv_load_wto_matrix); the
// object-to-world half is read by hit shaders only.
constexpr uint32_t kAmdInstanceFetchBytes = 64;
constexpr int kAmdBoxSlots = 4;

// Node types of the id's low bits (bvh.h: radv_bvh_node_*).
constexpr uint32_t kAmdTypeTriangle = 0, kAmdTypeBox16 = 4, kAmdTypeBox32 = 5, kAmdTypeInstance = 6;
constexpr uint32_t kAmdInvalidNode = 0xffffffffu;               // RADV_BVH_INVALID_NODE
constexpr uint32_t kAmdGeometryOpaque = 1u << 31;               // RADV_GEOMETRY_OPAQUE
constexpr uint32_t kAmdBarycentricsControl = 9;                 // radv_encode_triangle_gfx10_3
constexpr uint32_t kAmdBoxOnlyOpaque = 1, kAmdBoxNoOpaque = 2;  // VK_BVH_BOX_FLAG_* (vk_bvh.h)
// Byte offsets of radv_bvh_triangle_node and radv_bvh_box*_node fields.
constexpr size_t kAmdTriangleId = 48, kAmdTriangleGeometry = 52, kAmdTriangleControl = 60,
                 kAmdBoxCoords = 16, kAmdBox32Flags = 112;

// Half-precision (IEEE binary16) conversions: exact decode, and encodes rounded toward -inf
// (down) or +inf (up); beyond the largest half, up gives +inf and down gives 65504.
float half_to_float(uint16_t h);
uint16_t half_round_down(float value);
uint16_t half_round_up(float value);

// The id of a record at a byte offset from the level's first node; throws InputError (place
// "bvh") past the 32-bit offsets of radv's id_to_offset.
uint32_t amd_node_id(uint64_t offset, uint32_t type);

// box32 `flags`, a byte per child (encode.comp): a triangle child's
// VK_BVH_BOX_FLAG_ONLY_OPAQUE or _NO_OPAQUE from its triangle node (radv's fetch_child_flags);
// 0 for inner and instance children, as radv writes without VK_BUILD_FLAG_PROPAGATE_CULL_FLAGS
// (the build whose triangle `id` is 9). Run on a finished level; others are left alone.
void set_amd_box_flags(BvhImage& image);

void encode_amd_box(bool fp16, const WideNode& node, const ChildPlacement& placement,
                    const RecordRegions& regions, uint8_t* out);

// Writes radv_bvh_triangle_node for a triangle's vertices, id and opacity.
void encode_amd_triangle(const float vertices[9], uint32_t prim, bool opaque, uint8_t* out);

}  // namespace rtsim
