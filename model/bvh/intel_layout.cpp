#include "model/bvh/intel_layout.h"

#include <array>
#include <cstring>
#include <stdexcept>

#include "model/bvh/intel_nodes.h"

namespace rtsim {
namespace {

constexpr uint32_t kNone = ~0u;

struct Placer {
  const WideBvh& wide;
  const LeafRecords& leaves;
  BvhImage& image;
  std::vector<uint32_t> block;                         // per node: its block
  std::vector<std::array<uint32_t, kMaxWidth>> first;  // per node and slot: a leaf's first block
  std::vector<std::array<XeChild, kMaxWidth>> child;   // per node and slot: type and blocks
  std::vector<uint8_t> bytes;                          // every block, in order
  std::vector<uint32_t> treelet;                       // per block
  std::vector<bool> leaf;                              // per block
  uint32_t next = 0;

  void place_node(uint32_t n) {
    block[n] = next++;
    treelet.push_back(wide.nodes[n].treelet);
    leaf.push_back(false);
    bytes.resize(bytes.size() + kXeBlockBytes);
  }

  // A record of `size` bytes at the next blocks; returns where to write it (valid until the
  // next block is added).
  uint8_t* add_record(uint32_t size, uint32_t owner_treelet) {
    uint32_t blocks = size / kXeBlockBytes;
    treelet.insert(treelet.end(), blocks, owner_treelet);
    leaf.insert(leaf.end(), blocks, true);
    size_t at = bytes.size();
    bytes.resize(at + size_t(blocks) * kXeBlockBytes);
    next += blocks;
    return bytes.data() + at;
  }

  // The leaf children of node n, one after another.
  void place_leaves(uint32_t n) {
    const WideNode& node = wide.nodes[n];
    for (int s = 0; s < node.child_count; ++s) {
      const WideChild& c = node.child[s];
      if (!c.leaf()) continue;
      image.triangle_count += c.count;  // triangles (top level: instances)
      first[n][s] = next;
      uint32_t start = next;
      const uint32_t* prims = wide.prim_order.data() + c.first;
      if (!leaves.encode_pair) {  // instance leaves, one a leaf
        if (c.count != 1) throw std::logic_error("xe6: an instance leaf holds one instance");
        leaves.encode(prims[0], add_record(leaves.stride, node.treelet));
        child[n][s] = {kXeInstance, uint8_t(next - start)};
        continue;
      }
      if (c.count > 2) throw std::logic_error("xe6: a leaf holds at most 2 triangles");
      uint8_t* quad = add_record(kXeQuadBytes, node.treelet);
      bool paired = c.count == 2 && leaves.encode_pair(prims[0], prims[1], quad);
      if (!paired) {
        leaves.encode(prims[0], quad);
        if (c.count == 2) {
          set_xe_quad_last(quad, false);
          leaves.encode(prims[1], add_record(kXeQuadBytes, node.treelet));
        }
      }
      child[n][s] = {kXeQuad, uint8_t(next - start)};
    }
  }

  bool has_inner(uint32_t n) const {
    const WideNode& node = wide.nodes[n];
    for (int s = 0; s < node.child_count; ++s)
      if (!node.child[s].leaf()) return true;
    return false;
  }
};

}  // namespace

void place_xe_blocks(const WideBvh& wide, const std::vector<uint32_t>& order,
                     const LeafRecords& leaves, BvhImage& image) {
  size_t nodes = wide.nodes.size();
  Placer p{wide,
           leaves,
           image,
           std::vector<uint32_t>(nodes, kNone),
           std::vector<std::array<uint32_t, kMaxWidth>>(nodes),
           std::vector<std::array<XeChild, kMaxWidth>>(nodes)};
  std::vector<uint32_t> parent(nodes, kNone);
  for (uint32_t n = 0; n < nodes; ++n)
    for (int s = 0; s < wide.nodes[n].child_count; ++s)
      if (!wide.nodes[n].child[s].leaf()) parent[wide.nodes[n].child[s].node] = n;
  image.triangle_count = 0;
  // Blocks: each sibling group, then its parent's leaves, then the leaves of its members that
  // have no inner children.
  size_t group_start = 0;
  for (size_t i = 0; i < order.size(); ++i) {
    p.place_node(order[i]);
    if (i + 1 < order.size() && parent[order[i + 1]] == parent[order[i]]) continue;
    if (parent[order[i]] != kNone) p.place_leaves(parent[order[i]]);
    for (size_t m = group_start; m <= i; ++m)
      if (!p.has_inner(order[m])) p.place_leaves(order[m]);
    group_start = i + 1;
  }
  // Encode: each node's children run inner first (slot order), then leaves (slot order).
  image.node_count = static_cast<uint32_t>(order.size());
  image.nodes = std::move(p.bytes);
  for (uint32_t n : order) {
    const WideNode& node = wide.nodes[n];
    int slots[kXeNodeSlots], count = 0;
    for (int pass = 0; pass < 2; ++pass)
      for (int s = 0; s < node.child_count; ++s)
        if (node.child[s].leaf() == (pass == 1)) slots[count++] = s;
    uint32_t expected = kNone, run = 0;
    for (int i = 0; i < count; ++i) {
      const WideChild& c = node.child[slots[i]];
      uint32_t at = c.leaf() ? p.first[n][slots[i]] : p.block[c.node];
      if (!c.leaf()) p.child[n][slots[i]] = {kXeMixed, 1};
      if (i == 0) expected = run = at;
      if (at != expected || at <= p.block[n])
        throw std::logic_error("xe6: a node's children are not one run after it");
      expected += p.child[n][slots[i]].blocks;
    }
    encode_xe_node(node, slots, p.child[n].data(), p.block[n], run,
                   image.nodes.data() + size_t(p.block[n]) * kXeBlockBytes);
  }
  image.node_treelet = std::move(p.treelet);
  image.leaf_blocks = std::move(p.leaf);
  image.triangle_stride = kXeBlockBytes;
  image.interleaved = true;
}

}  // namespace rtsim
