// A two-level BVH over instanced geometry (traces/instances.h), as RT hardware walks it: a top
// level (TLAS) over the instances' world-space boxes whose leaves point at instance records,
// and a bottom level (BLAS) per unique mesh, in object space. Each level is a BvhImage in the
// configured node format, with treelets; one address space holds them in this order: TLAS
// nodes, instance records, then each BLAS's nodes and triangles (each region aligned to
// region_align). Unique geometry is held once, however many instances place it.
// Instance record (kInstanceRecordBytes): the world-to-object transform as 3x4 fp32 (the
// linear part's columns, then the offset: 48 bytes), the BLAS index, the instance id, padding.
#pragma once

#include <cstdint>
#include <vector>

#include "model/bvh/bvh_image.h"
#include "traces/instances.h"

namespace rtsim {

constexpr uint32_t kInstanceRecordBytes = 64;

struct InstanceRecord {
  Transform to_object;
  uint32_t blas = 0, instance = 0;
};

struct TwoLevelBvh {
  BvhImage top;                  // leaf records: instance records, one instance per leaf
  std::vector<BvhImage> bottom;  // per unique mesh, in InstancedMesh::meshes order

  uint64_t total_bytes() const;
  uint64_t node_count() const;      // over the levels
  uint64_t triangle_count() const;  // the unique ones: the bottom levels', or the one level's
};

// What the traversal and the timing model walk: one BVH image, or both levels of a two-level
// BVH (a TwoLevelBvh without bottom levels is one level). Cheap to copy; the images must
// outlive it. Treelets are numbered across levels (BvhImage::treelet_base).
struct BvhView {
  BvhView(const BvhImage& image) : top(&image) {}  // NOLINT: one level converts implicitly
  BvhView(const TwoLevelBvh& bvh)                  // NOLINT
      : top(&bvh.top), bottom(bvh.bottom.empty() ? nullptr : &bvh.bottom) {}

  const BvhImage* top;
  const std::vector<BvhImage>* bottom = nullptr;  // null: one level

  bool two_level() const { return bottom != nullptr; }
  // Every level, the top one first.
  std::vector<const BvhImage*> levels() const;
  uint32_t treelet_count() const;
  uint32_t root_treelet() const;
  // The byte range all levels occupy: [begin, end).
  uint64_t begin_address() const { return top->node_base; }
  uint64_t end_address() const;
  // The top level's nodes and records (two levels), or nothing: [begin, end).
  uint64_t top_end_address() const;
};

// The global id of the treelet of a level's node.
inline uint32_t node_treelet(const BvhImage& level, uint32_t position) {
  return level.node_treelet.empty() ? level.treelet_base
                                    : level.treelet_base + level.node_treelet[position];
}

// Reads the instance record at a position of the top level's leaf records.
InstanceRecord read_instance_record(const BvhImage& top, uint32_t position);

// Whether config.instancing asks for two levels over this geometry (auto: a mesh is placed
// more than once).
bool wants_two_levels(const BvhConfig& config, const InstancedMesh& geometry);

// The BVH of a scene under config.instancing: one level over `flat` (a TwoLevelBvh without
// bottom levels), or two over `instances`, whose flattening `flat` is. Two levels over a scene
// without instance structure (no instances) make it `flat` as one instance, in `instances`.
TwoLevelBvh build_scene_levels(const TriangleMesh& flat, InstancedMesh& instances,
                               const BvhConfig& config, const BvhBuildStep& on_step = {});

// Builds both levels. Throws as build_bvh_image does; InputError naming "instances" for
// geometry that instancing_problem() rejects.
TwoLevelBvh build_two_level_bvh(const InstancedMesh& geometry, const BvhConfig& config,
                                const BvhBuildStep& on_step = {});

}  // namespace rtsim
