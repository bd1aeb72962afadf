#include "model/bvh/bvh_image.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>
#include <glm/common.hpp>

#include "model/bvh/amd_nodes.h"
#include "model/bvh/binned_sah.h"
#include "model/bvh/intel_layout.h"
#include "model/bvh/intel_nodes.h"
#include "model/bvh/node_format.h"
#include "model/bvh/node_layout.h"
#include "model/bvh/triangle_format.h"
#include "model/bvh/wide_bvh.h"
#include "traces/error.h"
#include "traces/host_clock.h"
#include "traces/memory_plan.h"

namespace rtsim {
namespace {

uint32_t deepest_level(const WideBvh& bvh) {
  std::vector<uint32_t> depth(bvh.nodes.size(), 0);
  uint32_t deepest = 0;
  for (size_t n = 0; n < bvh.nodes.size(); ++n) {
    deepest = std::max(deepest, depth[n]);
    for (int c = 0; c < bvh.nodes[n].child_count; ++c)
      if (!bvh.nodes[n].child[c].leaf()) depth[bvh.nodes[n].child[c].node] = depth[n] + 1;
  }
  return deepest;
}

// The stride of records of `size` bytes that never span more `align`-byte blocks than they
// fill: a power of two up to the block (it divides the block), else whole blocks.
uint32_t padded_stride(uint32_t size, uint32_t align) {
  if (align == 0) return size;
  if (size > align) return (size + align - 1) / align * align;
  uint32_t stride = 1;
  while (stride < size) stride *= 2;
  return stride;
}

void place_regions(const WideBvh& wide, const std::vector<uint32_t>& order, size_t prims,
                   const LeafRecords& leaves, BvhImage& image);

}  // namespace

void set_scene_bounds(const Bounds& bounds, BvhImage& image) {
  image.scene_lo = bounds.lo;
  image.scene_hi = bounds.hi;
  glm::vec3 m = glm::max(glm::abs(bounds.lo), glm::abs(bounds.hi));
  image.scene_extent = std::max({m.x, m.y, m.z});
}

BvhImage build_bvh_image(const TriangleMesh& mesh, const BvhConfig& config,
                         const BvhBuildStep& on_step) {
  std::string problem = validate(config);
  if (!problem.empty()) throw_input_error("bvh config", "", problem);
  if (mesh.triangle_count() == 0) throw std::invalid_argument("build_bvh_image: no triangles");
  require_memory(mesh.triangle_count() * kBvhBuildBytesPerTriangle, "bvh",
                 fmt::format("building a BVH over {} triangles", mesh.triangle_count()),
                 "use a smaller scene");
  double start = wall_seconds();
  Bvh2 bvh2 = build_binned_sah(mesh, config);
  if (on_step) on_step("binned SAH build", wall_seconds() - start);
  LeafRecords triangles{triangle_stride(config.triangle_format), [&](uint32_t prim, uint8_t* out) {
                          encode_triangle(config.triangle_format, mesh, prim, out);
                        }};
  if (config.triangle_format == TriangleFormat::XeQuad)
    triangles.encode_pair = [&](uint32_t a, uint32_t b, uint8_t* out) {
      return encode_xe_quad(mesh, a, &b, out);
    };
  BvhImage image = encode_bvh_image(bvh2, config, triangles, on_step);
  set_scene_bounds(mesh_bounds(mesh), image);
  image.alpha = mesh.alpha;
  return image;
}

BvhImage encode_bvh_image(const Bvh2& bvh2, const BvhConfig& config, const LeafRecords& leaves,
                          const BvhBuildStep& on_step) {
  double step_start = wall_seconds();
  auto step = [&](const char* name) {
    double now = wall_seconds();
    if (on_step) on_step(name, now - step_start);
    step_start = now;
  };
  bool groups = config.node_format == NodeFormat::Cwbvh8 || config.node_format == NodeFormat::Xe6;

  BvhImage image;
  image.config = config;
  image.node_size = node_stride(config.node_format, config.width);
  image.node_stride = padded_stride(image.node_size, config.node_align);
  image.triangle_stride = leaves.stride;

  // Collapse, cut into treelets, order.
  WideBvh wide = collapse_bvh(bvh2, config.width);
  step("collapse");
  TreeletRule rule{image.node_stride, image.triangle_stride, groups, config.treelet_bytes,
                   config.treelet_budget};
  Treelets treelets = form_treelets(wide, rule);
  std::vector<uint32_t> order = order_nodes(wide, treelets, config.node_layout, groups);
  step("treelets and node order");
  image.node_base = config.node_base;
  if (config.node_format == NodeFormat::Xe6) {
    place_xe_blocks(wide, order, leaves, image);
    image.triangle_base = image.node_base;
  } else {
    place_regions(wide, order, bvh2.prim_order.size(), leaves, image);
  }
  step("encode");
  image.treelets = treelets.stats;
  image.stats.bvh2_nodes = static_cast<uint32_t>(bvh2.nodes.size());
  image.stats.bvh2_depth = bvh2.depth;
  image.stats.max_depth = deepest_level(wide);
  for (const WideNode& node : wide.nodes) {
    image.stats.child_slots_used += node.child_count;
    for (int c = 0; c < node.child_count; ++c) image.stats.leaves += node.child[c].leaf();
  }
  return image;
}

namespace {

// Two regions: nodes in `order`, then the leaf records, a node's leaves in slot order.
void place_regions(const WideBvh& wide, const std::vector<uint32_t>& order, size_t prims,
                   const LeafRecords& leaves, BvhImage& image) {
  const BvhConfig& config = image.config;
  std::vector<uint32_t> position(wide.nodes.size());
  for (uint32_t i = 0; i < order.size(); ++i) position[order[i]] = i;

  // Triangles follow the node order: a node's leaf children, in slot order.
  std::vector<uint32_t> tri_order;
  tri_order.reserve(prims);
  std::vector<ChildPlacement> placement(wide.nodes.size());
  for (uint32_t n : order) {
    const WideNode& node = wide.nodes[n];
    for (int c = 0; c < node.child_count; ++c) {
      const WideChild& child = node.child[c];
      if (child.leaf()) {
        placement[n].position[c] = static_cast<uint32_t>(tri_order.size());
        for (uint32_t i = 0; i < child.count; ++i)
          tri_order.push_back(wide.prim_order[child.first + i]);
      } else {
        placement[n].position[c] = position[child.node];
      }
    }
  }

  // Encode both regions and place them in the address space.
  image.node_count = static_cast<uint32_t>(order.size());
  image.triangle_count = static_cast<uint32_t>(tri_order.size());
  image.nodes.assign(size_t(image.node_count) * image.node_stride, 0);
  uint64_t nodes_end = image.node_base + image.nodes.size();
  image.triangle_base = (nodes_end + config.region_align - 1) & ~(config.region_align - 1);
  RecordRegions regions = image.regions();
  regions.instance_leaves = leaves.instances;
  image.node_treelet.resize(image.node_count);
  for (uint32_t i = 0; i < image.node_count; ++i) {
    const WideNode& node = wide.nodes[order[i]];
    encode_node(config.node_format, config.width, node, placement[order[i]],
                image.nodes.data() + size_t(i) * image.node_stride, regions);
    image.node_treelet[i] = node.treelet;
  }
  image.triangles.assign(size_t(image.triangle_count) * image.triangle_stride, 0);
  for (uint32_t i = 0; i < image.triangle_count; ++i)
    leaves.encode(tri_order[i], image.triangles.data() + size_t(i) * image.triangle_stride);
  set_amd_box_flags(image);
}

}  // namespace

}  // namespace rtsim
