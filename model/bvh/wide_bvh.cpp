#include "model/bvh/wide_bvh.h"

#include <stdexcept>

namespace rtsim {

WideBvh collapse_bvh(const Bvh2& bvh2, int width) {
  if (width < 2 || width > kMaxWidth) throw std::invalid_argument("collapse_bvh: bad width");
  WideBvh wide;
  wide.width = width;
  wide.prim_order = bvh2.prim_order;
  wide.nodes.reserve(bvh2.nodes.size() / 2 + 1);
  // Each task turns one binary node into one wide node.
  struct Task {
    uint32_t bvh2_node, wide_node;
  };
  std::vector<Task> tasks{{0, 0}};
  wide.nodes.emplace_back();
  while (!tasks.empty()) {
    Task task = tasks.back();
    tasks.pop_back();
    const Bvh2Node& source = bvh2.nodes[task.bvh2_node];
    std::array<uint32_t, kMaxWidth> kids{};
    int kid_count = 0;
    if (source.leaf()) {
      kids[kid_count++] = task.bvh2_node;
    } else {
      kids[kid_count++] = source.first;
      kids[kid_count++] = source.first + 1;
    }
    // Open the inner child with the largest surface area until the node is full.
    while (kid_count < width) {
      int best = -1;
      float best_area = -1.0f;
      for (int k = 0; k < kid_count; ++k) {
        const Bvh2Node& kid = bvh2.nodes[kids[k]];
        if (!kid.leaf() && kid.box.surface_area() > best_area) {
          best = k;
          best_area = kid.box.surface_area();
        }
      }
      if (best < 0) break;
      uint32_t opened = kids[best];
      kids[best] = bvh2.nodes[opened].first;
      kids[kid_count++] = bvh2.nodes[opened].first + 1;
    }
    // Emit the children: leaves keep their range, inner children become wide nodes.
    WideNode node;
    node.box = source.box;
    node.child_count = kid_count;
    for (int k = 0; k < kid_count; ++k) {
      const Bvh2Node& kid = bvh2.nodes[kids[k]];
      WideChild& child = node.child[k];
      child.box = kid.box;
      if (kid.leaf()) {
        child.first = kid.first;
        child.count = kid.count;
      } else {
        child.node = static_cast<uint32_t>(wide.nodes.size());
        wide.nodes.emplace_back();
        tasks.push_back({kids[k], child.node});
      }
    }
    wide.nodes[task.wide_node] = node;
  }
  return wide;
}

}  // namespace rtsim
