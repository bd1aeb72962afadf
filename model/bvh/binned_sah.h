// Binary BVH built top-down with the binned surface area heuristic (Wald, "On fast Construction
// of SAH-based Bounding Volume Hierarchies", IEEE RT 2007): each axis of the centroid bounds is
// cut into 16 or 32 bins and the cheapest bin boundary wins. Offline: no hardware is modeled.
#pragma once

#include <cstdint>
#include <vector>

#include "model/bvh/bvh_config.h"
#include "traces/ray.h"

namespace rtsim {

struct Bvh2Node {
  Bounds box;
  uint32_t first = 0;  // inner: index of the left child (the right one follows); leaf: prim_order
  uint32_t count = 0;  // triangles in a leaf; 0 for an inner node
  bool leaf() const { return count > 0; }
};

struct Bvh2 {
  std::vector<Bvh2Node> nodes;       // nodes[0] is the root
  std::vector<uint32_t> prim_order;  // triangle ids; a leaf holds [first, first + count)
  uint32_t depth = 0;                // levels below the root of the deepest leaf
};

// Builds over every triangle of the mesh (degenerate ones too: they never hit, but they stay
// in the tree so ids match the scene). Deterministic. Leaves hold at most max_leaf_size.
Bvh2 build_binned_sah(const TriangleMesh& mesh, const BvhConfig& config);
// The same over any primitives given by their boxes (a top level over instances).
Bvh2 build_binned_sah(const std::vector<Bounds>& boxes, const BvhConfig& config);

}  // namespace rtsim
