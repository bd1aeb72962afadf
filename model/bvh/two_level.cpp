#include "model/bvh/two_level.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "model/bvh/binned_sah.h"
#include "traces/error.h"

namespace rtsim {
namespace {

uint64_t align_up(uint64_t address, uint64_t align) {
  return (address + align - 1) / align * align;
}

// The first free address after an image, aligned for the next region.
uint64_t image_end(const BvhImage& image) {
  return align_up(image.triangle_base + image.triangles.size(), image.config.region_align);
}

void encode_instance_record(const InstanceRecord& r, uint8_t* out) {
  float xfm[12];
  for (int c = 0; c < 3; ++c)
    for (int row = 0; row < 3; ++row) xfm[c * 3 + row] = r.to_object.linear[c][row];
  for (int row = 0; row < 3; ++row) xfm[9 + row] = r.to_object.offset[row];
  std::memcpy(out, xfm, sizeof xfm);
  std::memcpy(out + 48, &r.blas, 4);
  std::memcpy(out + 52, &r.instance, 4);
}

// Treelets a level numbers (the ids its nodes carry may exceed the count formed).
uint32_t local_treelets(const BvhImage& image) {
  uint32_t count = std::max<uint32_t>(image.treelets.count, 1);
  for (uint32_t t : image.node_treelet) count = std::max(count, t + 1);
  return count;
}

}  // namespace

std::vector<const BvhImage*> BvhView::levels() const {
  std::vector<const BvhImage*> out{top};
  if (bottom)
    for (const BvhImage& b : *bottom) out.push_back(&b);
  return out;
}

uint32_t BvhView::treelet_count() const {
  const BvhImage& last = bottom ? bottom->back() : *top;
  return last.treelet_base + local_treelets(last);
}

uint32_t BvhView::root_treelet() const {
  return node_treelet(*top, 0);
}

uint64_t BvhView::end_address() const {
  const BvhImage& last = bottom ? bottom->back() : *top;
  return last.triangle_base + last.triangles.size();
}

uint64_t BvhView::top_end_address() const {
  return bottom ? top->triangle_base + top->triangles.size() : top->node_base;
}

uint64_t TwoLevelBvh::total_bytes() const {
  uint64_t bytes = top.total_bytes();
  for (const BvhImage& b : bottom) bytes += b.total_bytes();
  return bytes;
}

uint64_t TwoLevelBvh::node_count() const {
  uint64_t nodes = top.node_count;
  for (const BvhImage& b : bottom) nodes += b.node_count;
  return nodes;
}

uint64_t TwoLevelBvh::triangle_count() const {
  if (bottom.empty()) return top.triangle_count;
  uint64_t triangles = 0;
  for (const BvhImage& b : bottom) triangles += b.triangle_count;
  return triangles;
}

InstanceRecord read_instance_record(const BvhImage& top, uint32_t position) {
  const uint8_t* in = top.triangle_bytes(position);
  float xfm[12];
  std::memcpy(xfm, in, sizeof xfm);
  InstanceRecord r;
  for (int c = 0; c < 3; ++c)
    for (int row = 0; row < 3; ++row) r.to_object.linear[c][row] = xfm[c * 3 + row];
  for (int row = 0; row < 3; ++row) r.to_object.offset[row] = xfm[9 + row];
  std::memcpy(&r.blas, in + 48, 4);
  std::memcpy(&r.instance, in + 52, 4);
  return r;
}

bool wants_two_levels(const BvhConfig& config, const InstancedMesh& geometry) {
  if (config.instancing != Instancing::Auto) return config.instancing == Instancing::TwoLevel;
  std::vector<uint32_t> placed(geometry.meshes.size(), 0);
  for (const Instance& inst : geometry.instances)
    if (inst.mesh < placed.size() && ++placed[inst.mesh] > 1) return true;
  return false;
}

TwoLevelBvh build_scene_levels(const TriangleMesh& flat, InstancedMesh& instances,
                               const BvhConfig& config, const BvhBuildStep& on_step) {
  if (!wants_two_levels(config, instances)) {
    TwoLevelBvh out;
    out.top = build_bvh_image(flat, config, on_step);
    return out;
  }
  if (instances.instances.empty()) {
    instances.meshes = {flat};
    instances.instances = {{0, Transform{}}};
  }
  return build_two_level_bvh(instances, config, on_step);
}

TwoLevelBvh build_two_level_bvh(const InstancedMesh& geometry, const BvhConfig& config,
                                const BvhBuildStep& on_step) {
  std::string problem = validate(config);
  if (!problem.empty()) throw_input_error("bvh config", "", problem);
  problem = instancing_problem(geometry);
  if (!problem.empty()) throw_input_error("instances", "", problem);
  TwoLevelBvh out;
  // Top level: one instance per leaf, so that each leaf is one transform.
  BvhConfig top_config = config;
  top_config.max_leaf_size = 1;
  std::vector<Bounds> mesh_boxes;
  for (const TriangleMesh& mesh : geometry.meshes) mesh_boxes.push_back(mesh_bounds(mesh));
  std::vector<Bounds> boxes;
  std::vector<InstanceRecord> records;
  for (size_t i = 0; i < geometry.instances.size(); ++i) {
    const Instance& inst = geometry.instances[i];
    boxes.push_back(world_box(mesh_boxes[inst.mesh], inst.to_world));
    records.push_back({inverse(inst.to_world), inst.mesh, uint32_t(i)});
  }
  Bvh2 top2 = build_binned_sah(boxes, top_config);
  LeafRecords instance_records{kInstanceRecordBytes, [&](uint32_t prim, uint8_t* out) {
                                 encode_instance_record(records[prim], out);
                               }};
  out.top = encode_bvh_image(top2, top_config, instance_records, on_step);
  Bounds world;
  for (const Bounds& b : boxes) world.grow(b);
  set_scene_bounds(world, out.top);
  // Bottom levels, one after another in the address space.
  uint64_t next = image_end(out.top);
  for (const TriangleMesh& mesh : geometry.meshes) {
    BvhConfig bottom_config = config;
    bottom_config.node_base = next;
    uint32_t treelet_base = BvhView(out).treelet_count();
    out.bottom.push_back(build_bvh_image(mesh, bottom_config, on_step));
    out.bottom.back().treelet_base = treelet_base;
    next = image_end(out.bottom.back());
  }
  return out;
}

}  // namespace rtsim
