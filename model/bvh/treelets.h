// Treelets: connected pieces of the wide BVH whose nodes fit a byte budget (512 B .. 64 KB),
// formed greedily by surface area as in Aila & Karras, "Architecture Considerations for Tracing
// Incoherent Rays" (HPG 2010): a treelet starts at a root and repeatedly adds the candidate with
// the largest surface area (the likeliest to be visited) until the next one does not fit; the
// candidates left over start new treelets. The ray scheduler queues rays per treelet, so this
// decides what one treelet fetch can serve. Offline: no hardware is modeled here.
//
// The unit added is one node, or, when the node format needs siblings stored contiguously
// (cwbvh8), the group of inner children of one node; such a group larger than the budget makes
// a treelet of its own and is counted as oversized.
//
// The budget counts a unit's node bytes, or its node bytes and the triangle bytes of its nodes'
// leaves (the triangles a ray in the treelet tests, which follow their nodes in memory).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "model/bvh/bvh_config.h"
#include "model/bvh/wide_bvh.h"

namespace rtsim {

struct TreeletRule {
  uint32_t node_bytes = 64;      // bytes: one node's record (its stride)
  uint32_t triangle_bytes = 40;  // bytes: one triangle's record
  bool sibling_groups = false;   // the unit added is a node's group of inner children
  uint32_t budget_bytes = 4096;  // bytes: most bytes of one treelet
  TreeletBudget budget = TreeletBudget::Nodes;  // what the budget counts
};

struct TreeletStats {
  uint32_t count = 0;         // treelets
  uint32_t oversized = 0;     // treelets over the budget (one sibling group)
  uint32_t budget_bytes = 0;  // bytes: the budget they were formed with
  TreeletBudget budget = TreeletBudget::Nodes;
  // Budgeted bytes (nodes, or nodes and triangles) per treelet.
  uint64_t min_bytes = 0, max_bytes = 0, total_bytes = 0;
  // Node and leaf-triangle bytes of all treelets, whatever the budget counts.
  uint64_t node_bytes = 0, triangle_bytes = 0, max_triangle_bytes = 0;
  // Treelets by fill: bin i holds size in (i/10, (i+1)/10] of the budget; bin 9 also > budget.
  std::array<uint32_t, 10> fill_histogram{};
};

struct Treelets {
  std::vector<std::vector<uint32_t>> nodes;  // per treelet, wide node ids in the order added
  TreeletStats stats;
};

// Forms the treelets and writes each node's treelet id into bvh.nodes[i].treelet.
Treelets form_treelets(WideBvh& bvh, const TreeletRule& rule);

}  // namespace rtsim
