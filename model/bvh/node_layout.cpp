#include "model/bvh/node_layout.h"

#include <algorithm>
#include <deque>

namespace rtsim {
namespace {

std::vector<uint32_t> inner_children(const WideNode& node) {
  std::vector<uint32_t> kids;
  for (int c = 0; c < node.child_count; ++c)
    if (!node.child[c].leaf()) kids.push_back(node.child[c].node);
  return kids;
}

// Pre-order: a node, then its first child's subtree, then the next one's.
std::vector<uint32_t> preorder(const WideBvh& bvh) {
  std::vector<uint32_t> order, stack{0};
  while (!stack.empty()) {
    uint32_t n = stack.back();
    stack.pop_back();
    order.push_back(n);
    auto kids = inner_children(bvh.nodes[n]);
    stack.insert(stack.end(), kids.rbegin(), kids.rend());
  }
  return order;
}

// Sibling groups in depth-first order: a node's group of children, then each child's group.
std::vector<uint32_t> group_preorder(const WideBvh& bvh) {
  std::vector<uint32_t> order{0}, stack{0};
  while (!stack.empty()) {
    uint32_t n = stack.back();
    stack.pop_back();
    auto kids = inner_children(bvh.nodes[n]);
    order.insert(order.end(), kids.begin(), kids.end());
    stack.insert(stack.end(), kids.rbegin(), kids.rend());
  }
  return order;
}

// Level order: a node's children are appended when the node is reached, so they are adjacent.
std::vector<uint32_t> level_order(const WideBvh& bvh) {
  std::vector<uint32_t> order{0};
  for (size_t i = 0; i < order.size(); ++i) {
    auto kids = inner_children(bvh.nodes[order[i]]);
    order.insert(order.end(), kids.begin(), kids.end());
  }
  return order;
}

}  // namespace

std::vector<uint32_t> order_nodes(const WideBvh& bvh, const Treelets& treelets, NodeLayout layout,
                                  bool sibling_groups) {
  switch (layout) {
    case NodeLayout::DepthFirst: return sibling_groups ? group_preorder(bvh) : preorder(bvh);
    case NodeLayout::BreadthFirst: return level_order(bvh);
    default: {
      std::vector<uint32_t> order;
      order.reserve(bvh.nodes.size());
      for (const auto& nodes : treelets.nodes)
        order.insert(order.end(), nodes.begin(), nodes.end());
      return order;
    }
  }
}

}  // namespace rtsim
