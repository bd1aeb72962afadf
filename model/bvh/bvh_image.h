// The BVH as the hardware sees it: encoded nodes and triangles at addresses of a simulated
// address space, plus the facts about it that the model reports (sizes, treelets, depth).
// Address space: nodes from config.node_base, node i at node_base + i * node_stride; the
// triangle region starts at the next multiple of config.region_align after the last node.
// With config.node_align, node_stride is the record's size padded so that no node spans more
// aligned blocks than it fills (the next power of two up to the block, else a multiple of it).
// Interleaved formats (xe6, model/bvh/intel_layout.h): one region of 64-byte blocks holds nodes
// and leaf records; a position is a block, triangle_base = node_base.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "model/bvh/bvh_config.h"
#include "model/bvh/node_format.h"
#include "model/bvh/treelets.h"
#include "traces/ray.h"

namespace rtsim {

struct BvhBuildStats {
  uint32_t bvh2_nodes = 0;        // nodes of the binary BVH before collapsing
  uint32_t bvh2_depth = 0;        // levels below the root of its deepest leaf
  uint32_t leaves = 0;            // leaf children in the wide BVH
  uint32_t max_depth = 0;         // levels below the root of the deepest wide node
  uint32_t child_slots_used = 0;  // children over all wide nodes (fill = used / nodes / width)
};

struct BvhImage {
  BvhConfig config;
  uint32_t node_stride = 0, triangle_stride = 0;  // bytes per record, padding included
                                                  // (triangle: any leaf record)
  uint32_t node_size = 0;                         // bytes a node fetch reads (no padding)
  uint32_t node_count = 0, triangle_count = 0;
  uint64_t node_base = 0, triangle_base = 0;  // addresses of the two regions
  std::vector<uint8_t> nodes, triangles;      // the bytes of the two regions
  std::vector<uint32_t> node_treelet;         // treelet id of the node at each position
  bool interleaved = false;                   // xe6: leaf records are blocks of `nodes`
  std::vector<bool> leaf_blocks;              // interleaved: position holds a leaf record
  // Two levels' top with xe6: each BLAS's root address (instance leaves point at it).
  std::vector<uint64_t> blas_roots;
  uint32_t treelet_base = 0;  // two levels: added to node_treelet to number treelets across levels
  TreeletStats treelets;
  BvhBuildStats stats;
  float scene_extent = 0.0f;                 // largest |coordinate| of any vertex
  glm::vec3 scene_lo{0.0f}, scene_hi{0.0f};  // the vertices' bounding box
  // The mesh's alpha-tested triangles (traces/alpha.h), by the prim ids of the triangle
  // records; null: all opaque. The traversal asks it about each candidate hit.
  std::shared_ptr<const TriangleAlpha> alpha;

  uint64_t node_address(uint32_t position) const {
    return node_base + uint64_t(position) * node_stride;
  }
  uint64_t triangle_address(uint32_t position) const {
    return triangle_base + uint64_t(position) * triangle_stride;
  }
  const uint8_t* node_bytes(uint32_t position) const {
    return nodes.data() + size_t(position) * node_stride;
  }
  const uint8_t* triangle_bytes(uint32_t position) const {
    return (interleaved ? nodes : triangles).data() + size_t(position) * triangle_stride;
  }
  // Positions of the node region (nodes; interleaved: blocks) and whether one holds a node.
  uint32_t positions() const { return uint32_t(nodes.size() / node_stride); }
  bool holds_node(uint32_t position) const { return !interleaved || !leaf_blocks[position]; }
  // The first byte after the image's regions.
  uint64_t end_address() const {
    return interleaved ? node_base + nodes.size() : triangle_base + triangles.size();
  }
  // Where the records lie, for formats whose children are byte offsets (amd_nodes.h).
  RecordRegions regions() const {
    return {node_stride, triangle_stride, triangle_base - node_base, false};
  }
  uint64_t total_bytes() const { return nodes.size() + triangles.size(); }
  uint64_t node_padding_bytes() const { return uint64_t(node_count) * (node_stride - node_size); }
};

// Peak bytes a build takes per triangle beyond the mesh (measured: 160 on grid:1000000 and
// grid:2000000 with the defaults, of which the finished image keeps about 85), rounded up.
constexpr uint64_t kBvhBuildBytesPerTriangle = 176;

// Called after each step of a build with its name and host seconds.
using BvhBuildStep = std::function<void(const char* step, double seconds)>;

struct Bvh2;

// The records leaves point at: triangles, or a top level's instance records.
struct LeafRecords {
  uint32_t stride = 0;                                      // bytes per record
  std::function<void(uint32_t prim, uint8_t* out)> encode;  // writes record `prim`
  bool instances = false;  // instance records (a top level), else triangles
  // xe_quad: writes triangles a and b as one record if they can share it (else false).
  std::function<bool(uint32_t a, uint32_t b, uint8_t* out)> encode_pair;
};

// Collapses a binary BVH, forms treelets, orders and encodes its nodes and leaf records (the
// part of build_bvh_image after the binary build). Leaves scene bounds unset.
BvhImage encode_bvh_image(const Bvh2& bvh2, const BvhConfig& config, const LeafRecords& leaves,
                          const BvhBuildStep& on_step = {});

// Sets scene_lo, scene_hi and scene_extent (largest |coordinate|) from the geometry's bounds.
void set_scene_bounds(const Bounds& bounds, BvhImage& image);

// Builds, collapses, forms treelets, orders and encodes. Throws InputError (via
// throw_input_error with place "bvh config") for an invalid config, or naming "bvh" when the
// build needs more memory than there is (memory_plan.h), std::invalid_argument for a mesh
// without triangles.
BvhImage build_bvh_image(const TriangleMesh& mesh, const BvhConfig& config,
                         const BvhBuildStep& on_step = {});

}  // namespace rtsim
