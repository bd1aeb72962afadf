// Order of the wide nodes in the simulated address space: depth-first, breadth-first or
// treelet by treelet. The order decides which nodes share cache lines and DRAM pages.
// Offline: no hardware is modeled here.
#pragma once

#include <cstdint>
#include <vector>

#include "model/bvh/bvh_config.h"
#include "model/bvh/treelets.h"
#include "model/bvh/wide_bvh.h"

namespace rtsim {

// order[i] is the wide node stored at position i; order[0] is the root. With sibling_groups
// (cwbvh8) the inner children of every node are stored next to each other, in slot order.
std::vector<uint32_t> order_nodes(const WideBvh& bvh, const Treelets& treelets, NodeLayout layout,
                                  bool sibling_groups);

}  // namespace rtsim
