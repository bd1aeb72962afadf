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
};

// Reads the instance record at a position of the top level's leaf records.
InstanceRecord read_instance_record(const BvhImage& top, uint32_t position);

// Builds both levels. Throws as build_bvh_image does; InputError naming "instances" for
// geometry that instancing_problem() rejects.
TwoLevelBvh build_two_level_bvh(const InstancedMesh& geometry, const BvhConfig& config,
                                const BvhBuildStep& on_step = {});

}  // namespace rtsim
