#include "model/bvh/bvh_config.h"

#include <fmt/core.h>

namespace rtsim {
namespace {

// radv's box nodes have 4 child slots, each pointing at one node or one triangle node.
std::string amd_problem(const BvhConfig& c) {
  const char* name = node_format_name(c.node_format);
  if (c.width > 4)
    return fmt::format("width is {}: {} nodes hold at most 4 children (set bvh.width = 4)", c.width,
                       name);
  if (c.max_leaf_size != 1)
    return fmt::format(
        "max_leaf_size is {}: each child of an {} node is one triangle node (set "
        "bvh.max_leaf_size = 1)",
        c.max_leaf_size, name);
  if (c.triangle_format != TriangleFormat::AmdTriangle)
    return fmt::format(
        "triangle_format is {}: {} nodes point at amd_tri triangle nodes (set "
        "bvh.triangle_format = \"amd_tri\")",
        triangle_format_name(c.triangle_format), name);
  return {};
}

// Intel's quads are interleaved with its nodes (Mesa anv_bvh.h): either both or neither.
std::string xe_problem(const BvhConfig& c) {
  bool xe_node = c.node_format == NodeFormat::Xe6,
       xe_leaf = c.triangle_format == TriangleFormat::XeQuad;
  if (xe_node != xe_leaf)
    return "node_format xe6 and triangle_format xe_quad go together: Intel's leaves are quads "
           "interleaved with its nodes";
  if (xe_node && c.width > 6)
    return fmt::format("width is {}: xe6 nodes hold at most 6 children", c.width);
  if (xe_node && c.max_leaf_size > 2)
    return fmt::format(
        "max_leaf_size is {}: xe6 leaves hold at most 2 triangles (one quad, or two)",
        c.max_leaf_size);
  return {};
}

}  // namespace

std::string validate(const BvhConfig& c) {
  if (c.sah_bins != 16 && c.sah_bins != 32)
    return fmt::format("sah_bins is {}: it must be 16 or 32", c.sah_bins);
  if (c.max_leaf_size < 1 || c.max_leaf_size > 254)
    return fmt::format("max_leaf_size is {}: it must be in 1..254", c.max_leaf_size);
  if (c.node_format == NodeFormat::Cwbvh8 && c.max_leaf_size > 3)
    return fmt::format("max_leaf_size is {}: cwbvh8 leaves hold at most 3 triangles",
                       c.max_leaf_size);
  if (is_amd_format(c.node_format)) {
    std::string problem = amd_problem(c);
    if (!problem.empty()) return problem;
  }
  std::string problem = xe_problem(c);
  if (!problem.empty()) return problem;
  if (!(c.sah_node_cost >= 0.0f && c.sah_node_cost < 1e6f))
    return "sah_node_cost must be a finite value >= 0";
  if (c.width < 2 || c.width > 8) return fmt::format("width is {}: it must be in 2..8", c.width);
  if (c.treelet_bytes < 512 || c.treelet_bytes > 65536)
    return fmt::format("treelet_bytes is {}: it must be in 512..65536", c.treelet_bytes);
  if (c.region_align == 0 || (c.region_align & (c.region_align - 1)) != 0)
    return fmt::format("region_align is {}: it must be a power of two", c.region_align);
  if (c.node_base % 64 != 0) return "node_base must be 64-byte aligned";
  if (c.node_align != 0 &&
      ((c.node_align & (c.node_align - 1)) != 0 || c.node_align < 16 || c.node_align > 4096))
    return fmt::format("node_align is {}: it must be 0 or a power of two in 16..4096",
                       c.node_align);
  if (c.node_align > 64 && c.node_base % c.node_align != 0)
    return fmt::format("node_base must be a multiple of node_align ({})", c.node_align);
  return {};
}

const char* node_format_name(NodeFormat format) {
  switch (format) {
    case NodeFormat::Cwbvh8: return "cwbvh8";
    case NodeFormat::AmdBox32: return "amd_box32";
    case NodeFormat::AmdBox16: return "amd_box16";
    case NodeFormat::Xe6: return "xe6";
    default: return "aabb32";
  }
}

const char* triangle_format_name(TriangleFormat format) {
  switch (format) {
    case TriangleFormat::Woop: return "woop";
    case TriangleFormat::AmdTriangle: return "amd_tri";
    case TriangleFormat::XeQuad: return "xe_quad";
    default: return "raw";
  }
}

std::vector<std::string> node_format_names() {
  return {"aabb32", "cwbvh8", "amd_box32", "amd_box16", "xe6"};
}

std::vector<std::string> triangle_format_names() {
  return {"raw", "woop", "amd_tri", "xe_quad"};
}

const char* node_layout_name(NodeLayout layout) {
  switch (layout) {
    case NodeLayout::DepthFirst: return "depth-first";
    case NodeLayout::BreadthFirst: return "breadth-first";
    default: return "treelet";
  }
}

const char* treelet_budget_name(TreeletBudget budget) {
  return budget == TreeletBudget::NodesAndTriangles ? "nodes_and_triangles" : "nodes";
}

std::optional<NodeFormat> node_format_from_name(const std::string& name) {
  for (NodeFormat f : {NodeFormat::Aabb32, NodeFormat::Cwbvh8, NodeFormat::AmdBox32,
                       NodeFormat::AmdBox16, NodeFormat::Xe6})
    if (name == node_format_name(f)) return f;
  return std::nullopt;
}

std::optional<TriangleFormat> triangle_format_from_name(const std::string& name) {
  for (TriangleFormat f : {TriangleFormat::Raw, TriangleFormat::Woop, TriangleFormat::AmdTriangle,
                           TriangleFormat::XeQuad})
    if (name == triangle_format_name(f)) return f;
  return std::nullopt;
}

std::optional<NodeLayout> node_layout_from_name(const std::string& name) {
  if (name == "depth-first" || name == "dfs") return NodeLayout::DepthFirst;
  if (name == "breadth-first" || name == "bfs") return NodeLayout::BreadthFirst;
  if (name == "treelet") return NodeLayout::Treelet;
  return std::nullopt;
}

const char* instancing_name(Instancing instancing) {
  switch (instancing) {
    case Instancing::Flatten: return "flatten";
    case Instancing::TwoLevel: return "two_level";
    default: return "auto";
  }
}

std::optional<Instancing> instancing_from_name(const std::string& name) {
  for (Instancing i : {Instancing::Auto, Instancing::Flatten, Instancing::TwoLevel})
    if (name == instancing_name(i)) return i;
  return std::nullopt;
}

std::optional<TreeletBudget> treelet_budget_from_name(const std::string& name) {
  if (name == "nodes") return TreeletBudget::Nodes;
  if (name == "nodes_and_triangles") return TreeletBudget::NodesAndTriangles;
  return std::nullopt;
}

std::string describe(const BvhConfig& c) {
  std::string text =
      fmt::format("bvh{} {} {} {}", c.width, node_format_name(c.node_format),
                  triangle_format_name(c.triangle_format), node_layout_name(c.node_layout));
  if (c.node_align) text += fmt::format(" aligned {} B", c.node_align);
  const char* counted =
      c.treelet_budget == TreeletBudget::NodesAndTriangles ? " with triangles" : "";
  return text + fmt::format(" (treelets {} B{}, leaves <= {}, {} bins)", c.treelet_bytes, counted,
                            c.max_leaf_size, c.sah_bins);
}

}  // namespace rtsim
