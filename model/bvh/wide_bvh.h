// Wide BVH (BVH2 .. BVH8) collapsed from a binary one: a node adopts the children of its largest
// inner child (by surface area) until it has `width` children, as in Wald et al., "Getting Rid
// of Packets" (RT 2008) and Embree's BVH4/BVH8 builders. Leaves stay the binary BVH's leaves.
// Offline: no hardware is modeled; the formats in node_format.h encode the result.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "model/bvh/binned_sah.h"

namespace rtsim {

constexpr int kMaxWidth = 8;

struct WideChild {
  Bounds box;
  uint32_t node = 0;   // inner child: index into WideBvh::nodes
  uint32_t first = 0;  // leaf child: first index into WideBvh::prim_order
  uint32_t count = 0;  // leaf child: triangles; 0 for an inner child
  bool leaf() const { return count > 0; }
};

struct WideNode {
  Bounds box;
  std::array<WideChild, kMaxWidth> child;
  int child_count = 0;
  uint32_t treelet = 0;  // id of the treelet holding this node (treelets.h)
};

struct WideBvh {
  int width = 8;
  std::vector<WideNode> nodes;       // nodes[0] is the root; a parent precedes its children
  std::vector<uint32_t> prim_order;  // triangle ids, as in the binary BVH
};

// The root is always an inner node; a one-leaf binary BVH gives a root with one leaf child.
WideBvh collapse_bvh(const Bvh2& bvh2, int width);

}  // namespace rtsim
