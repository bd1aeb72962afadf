// A two-level BVH over instanced geometry (traces/instances.h), as RT hardware walks it: a top
// level (TLAS) over the instances' world-space boxes whose leaves point at instance records,
// and a bottom level (BLAS) per unique mesh, in object space. Each level is a BvhImage in the
// configured node format, with treelets; one address space holds them in this order: TLAS
// nodes, instance records, then each BLAS's nodes and triangles (each region aligned to
// region_align). Unique geometry is held once, however many instances place it.
// Instance record (kInstanceRecordBytes; amd formats: radv's 128-byte instance node,
// amd_instances.h; xe6: Intel's 128-byte instance leaf, intel_nodes.h, of which traversal reads
// the first 64 bytes): the world-to-object transform as 3x4 fp32 (the
// linear part's columns, then the offset: 48 bytes), the BLAS index, the instance id, the
// visibility mask (one byte), padding.
// Animated instances (traces/instance_settings.h): each frame has its own top level over the
// instances as they stand in that frame, rebuilt as a renderer rebuilds its TLAS per frame, in
// its own address range (frame 0's, then frame 1's, ...: a rebuilt TLAS starts cold in the
// caches); the bottom levels follow them and are shared by every frame.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "model/bvh/bvh_image.h"
#include "traces/instance_settings.h"

namespace rtsim {

constexpr uint32_t kInstanceRecordBytes = 64;

struct InstanceRecord {
  Transform to_object;
  uint32_t blas = 0, instance = 0;
  uint8_t mask = kAllInstances;
  Transform to_world;  // kept by amd instance nodes and xe6 instance leaves
};

// Bytes of one instance record of a top level in this node format (amd: radv's instance node),
// and the bytes an instance step reads of it.
uint32_t instance_record_bytes(NodeFormat format);
uint32_t instance_fetch_bytes(NodeFormat format);

// What building one frame's top level took: the figures a BVH-builder unit would need.
struct TopLevelBuild {
  uint32_t nodes = 0;    // nodes written
  uint64_t bytes = 0;    // node and instance record bytes written
  double seconds = 0.0;  // host time of this build
};

struct TwoLevelBvh {
  BvhImage top;                           // frame 0's; leaf records: instance records, one per leaf
  std::vector<BvhImage> frame_tops;       // animated: frames 1.. (empty: every frame uses `top`)
  std::vector<BvhImage> bottom;           // per unique mesh, in InstancedMesh::meshes order
  std::vector<TopLevelBuild> top_builds;  // two levels: per frame (one without motion)
  std::array<uint8_t, kRayTypeCount> ray_masks = all_ray_masks();  // the rays' inclusion masks

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
      : top(&bvh.top),
        frame_tops(bvh.frame_tops.empty() ? nullptr : &bvh.frame_tops),
        bottom(bvh.bottom.empty() ? nullptr : &bvh.bottom),
        ray_masks(&bvh.ray_masks) {}

  const BvhImage* top;                                // frame 0's top level, or the only level
  const std::vector<BvhImage>* frame_tops = nullptr;  // animated: frames 1..
  const std::vector<BvhImage>* bottom = nullptr;      // null: one level
  const std::array<uint8_t, kRayTypeCount>* ray_masks = nullptr;  // null: every ray sees all

  bool two_level() const { return bottom != nullptr; }
  // True if any triangle is alpha-tested (traces/alpha.h).
  bool alpha_tested() const {
    if (!bottom) return top->alpha != nullptr;
    for (const BvhImage& b : *bottom)
      if (b.alpha) return true;
    return false;
  }
  // The top level a ray of this frame starts in (frames past the last: the last's).
  const BvhImage& top_of(uint32_t frame) const {
    if (!frame_tops || frame == 0) return *top;
    return (*frame_tops)[std::min<size_t>(frame, frame_tops->size()) - 1];
  }
  uint8_t ray_mask(RayType type) const {
    return ray_masks ? (*ray_masks)[size_t(type)] : kAllInstances;
  }
  // Every level: the top ones (frame by frame) first.
  std::vector<const BvhImage*> levels() const;
  uint32_t treelet_count() const;
  uint32_t root_treelet(uint32_t frame = 0) const;
  std::vector<uint32_t> root_treelets() const;  // per frame
  // The byte range all levels occupy: [begin, end).
  uint64_t begin_address() const { return top->node_base; }
  uint64_t end_address() const;
  // The top levels' nodes and records (two levels, every frame's), or nothing: [begin, end).
  uint64_t top_end_address() const;
};

// The global id of the treelet of a level's node.
inline uint32_t node_treelet(const BvhImage& level, uint32_t position) {
  return level.node_treelet.empty() ? level.treelet_base
                                    : level.treelet_base + level.node_treelet[position];
}

// Reads the instance record at a position of the top level's leaf records; amd instance nodes
// name their BLAS by address and need the bottom levels (else std::logic_error).
InstanceRecord read_instance_record(const BvhImage& top, uint32_t position,
                                    const std::vector<BvhImage>* bottom = nullptr);

// Whether config.instancing asks for two levels over this geometry (auto: a mesh is placed
// more than once).
bool wants_two_levels(const BvhConfig& config, const InstancedMesh& geometry);

// The BVH of a scene under config.instancing: one level over `flat` (a TwoLevelBvh without
// bottom levels), or two over `instances`, whose flattening `flat` is. Two levels over a scene
// without instance structure (no instances) make it `flat` as one instance, in `instances`.
// Settings that are not empty need two levels: InputError naming "bvh.instancing" under
// "flatten".
TwoLevelBvh build_scene_levels(const TriangleMesh& flat, InstancedMesh& instances,
                               const BvhConfig& config, const BvhBuildStep& on_step = {},
                               const InstanceSettings& settings = {});

// Builds both levels, a top level per frame where settings move instances; masks are the
// instances'. Throws as build_bvh_image does; InputError naming "instances" for geometry that
// instancing_problem() or settings_problem() rejects.
TwoLevelBvh build_two_level_bvh(const InstancedMesh& geometry, const BvhConfig& config,
                                const BvhBuildStep& on_step = {},
                                const InstanceSettings& settings = {});

}  // namespace rtsim
