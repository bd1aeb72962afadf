// The xe6 image: internal nodes and leaf records interleaved in one region of 64-byte blocks,
// as Mesa's anv driver lays a BVH out (src/intel/vulkan/bvh/anv_bvh.h, struct bvh_layout:
// "start with root node, followed by interleaving internal nodes and leaves"). A node's
// children are one contiguous run: its inner children (a sibling group of order_nodes), then its
// leaves. Leaves go right after the sibling group of their parent's inner children, or, for a
// node without inner children, after the group the node itself belongs to.
// Offline: no hardware is modeled here; the records are model/bvh/intel_nodes.h's.
#pragma once

#include <cstdint>
#include <vector>

#include "model/bvh/bvh_image.h"
#include "model/bvh/wide_bvh.h"

namespace rtsim {

// Places and encodes every block of `wide` in `order` (node ids with sibling groups contiguous)
// into image.nodes: sets node_count (internal nodes), triangle_count (the leaves' triangles or
// instances), node_treelet and leaf_blocks per block, triangle_base = node_base. Leaf records:
// quads (leaves.encode_pair set: a leaf's two triangles share one quad when they can) or instance
// leaves of leaves.stride bytes. Throws std::logic_error if a node's children are not one run.
void place_xe_blocks(const WideBvh& wide, const std::vector<uint32_t>& order,
                     const LeafRecords& leaves, BvhImage& image);

}  // namespace rtsim
