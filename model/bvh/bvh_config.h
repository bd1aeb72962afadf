// Configuration of the BVH that the hardware traverses: how it is built (binned SAH), collapsed
// to a wide tree, encoded (node and triangle formats), ordered in memory and cut into treelets.
// Every field has a default, a unit and a one-line description; validate() names a bad field.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rtsim {

enum class NodeFormat : uint8_t {
  Aabb32,  // uncompressed fp32 child boxes, 64-byte aligned node of 2..8 children
  Cwbvh8,  // Ylitie et al. 2017 compressed 8-wide node: 80 bytes, 8-bit quantized child boxes
  // AMD RDNA2/3 (radv_bvh_box32_node): 128 bytes, 4 children, fp32 boxes
  AmdBox32,
  // AMD RDNA2/3 (radv_bvh_box16_node): 64 bytes, 4 children, fp16 boxes rounded outward
  AmdBox16,
  // Intel Xe (Mesa anv_internal_node): 64 bytes, 6 children, nodes and leaves in one region of
  // 64-byte blocks (model/bvh/intel_nodes.h)
  Xe6,
};

enum class TriangleFormat : uint8_t {
  Raw,   // three fp32 vertices + primitive id: 40 bytes; watertight test (Woop et al. 2013)
  Woop,  // precomputed affine unit-triangle transform + primitive id: 52 bytes (Woop 2004)

  // AMD RDNA2/3 triangle node (radv_bvh_triangle_node): 64 bytes, watertight test
  AmdTriangle,
  // Intel Xe quad leaf (Mesa anv_quad_leaf_node): 64 bytes, two triangles sharing four vertices;
  // with xe6 only
  XeQuad,
};

// The AMD RDNA2/3 node formats (amd_nodes.h): 4 children, one triangle node per leaf.
inline bool is_amd_format(NodeFormat format) {
  return format == NodeFormat::AmdBox32 || format == NodeFormat::AmdBox16;
}

enum class NodeLayout : uint8_t {
  DepthFirst,    // pre-order (aabb32); sibling groups in depth-first order (cwbvh8)
  BreadthFirst,  // level by level
  Treelet,       // treelet by treelet, each treelet contiguous (Aila & Karras 2010)
};

enum class TreeletBudget : uint8_t {
  Nodes,              // a treelet's budget counts its nodes
  NodesAndTriangles,  // and the triangles of its nodes' leaves
};

enum class Instancing : uint8_t {
  Auto,      // two levels when the scene places a mesh more than once, else one
  Flatten,   // one level over the world-space triangles
  TwoLevel,  // a TLAS over the instances and a BLAS per mesh (a flat scene: one instance)
};

struct BvhConfig {
  Instancing instancing = Instancing::Auto;
  int sah_bins = 16;           // bins per axis of the binned SAH build: 16 or 32
  int max_leaf_size = 3;       // triangles: most triangles in one leaf (cwbvh8: <= 3; amd: 1)
  float sah_node_cost = 1.0f;  // SAH cost of a node visit, in triangle tests
  int width = 8;               // children: most children of one node, 2..8 (amd: <= 4)
  NodeFormat node_format = NodeFormat::Aabb32;
  TriangleFormat triangle_format = TriangleFormat::Raw;
  NodeLayout node_layout = NodeLayout::Treelet;
  uint32_t treelet_bytes = 4096;  // bytes: budget of one treelet, 512..65536
  TreeletBudget treelet_budget = TreeletBudget::Nodes;
  // bytes: 0 packs nodes; else a power of two (the L1 line or sector): nodes are padded so that
  // none spans more blocks of this size than it fills
  uint32_t node_align = 0;
  uint64_t node_base = 0x10000000;  // address: first byte of the node region
  uint64_t region_align = 4096;     // bytes: the triangle region starts on this alignment
};

// Empty if the config is usable, else one line naming the field and the allowed values.
std::string validate(const BvhConfig& config);

const char* node_format_name(NodeFormat format);
const char* triangle_format_name(TriangleFormat format);
const char* node_layout_name(NodeLayout layout);
const char* treelet_budget_name(TreeletBudget budget);  // nodes, nodes_and_triangles
const char* instancing_name(Instancing instancing);     // auto, flatten, two_level
std::vector<std::string> node_format_names();           // every node format, in enum order
std::vector<std::string> triangle_format_names();       // every triangle format, in enum order
std::optional<NodeFormat> node_format_from_name(const std::string& name);
std::optional<TriangleFormat> triangle_format_from_name(const std::string& name);
std::optional<NodeLayout> node_layout_from_name(const std::string& name);
std::optional<TreeletBudget> treelet_budget_from_name(const std::string& name);
std::optional<Instancing> instancing_from_name(const std::string& name);

// "bvh8 aabb32 raw treelet(4096 B)": how a config is named in reports.
std::string describe(const BvhConfig& config);

}  // namespace rtsim
