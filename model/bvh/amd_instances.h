// AMD RDNA2/3 instance node, byte for byte as Mesa's radv writes it: struct
// radv_bvh_instance_node (src/amd/vulkan/bvh/bvh.h; 128 bytes, asserted in
// radv_GetAccelerationStructureBuildSizesKHR), written by radv_encode_instance_gfx10_3
// (src/amd/vulkan/bvh/encode.h). The top level of an amd_box32/amd_box16 BVH points at these
// (node type 6) instead of rtsim's 64-byte instance records. Fields:
//   0 bvh_ptr (u64): addr_to_node(BLAS root address) = (address >> 3) & (2^45 - 1)
//   8 custom_instance_and_mask: instance index (24 bits) | visibility mask << 24
//  12 sbt_offset_and_flags: 0 (no SBT offset, no instance flags)
//  16 wto_matrix: world to object, 3 rows of (linear row, offset)
//  64 instance_id: the instance index;  68 bvh_offset: 0 (rtsim's levels have no header)
//  72 reserved[2];  80 otw_matrix: object to world, as wto_matrix
// The traversal reads the first kAmdInstanceFetchBytes (amd_nodes.h).
#pragma once

#include <cstdint>
#include <vector>

#include "model/bvh/two_level.h"

namespace rtsim {

// Writes the node with bvh_ptr holding r.blas, until link_amd_instances() writes the address.
void encode_amd_instance(const InstanceRecord& r, uint8_t* out);

// Points every instance node of a top level at its bottom level's root, as radv's encoder does
// once the BLAS addresses are known.
void link_amd_instances(BvhImage& top, const std::vector<BvhImage>& bottom);

// Reads a linked instance node; the BLAS is the bottom level whose root bvh_ptr names. Throws
// std::logic_error if none does.
InstanceRecord read_amd_instance(const uint8_t* in, const std::vector<BvhImage>& bottom);

}  // namespace rtsim
