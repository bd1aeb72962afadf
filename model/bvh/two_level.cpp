#include "model/bvh/two_level.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "model/bvh/amd_instances.h"
#include "model/bvh/amd_nodes.h"
#include "model/bvh/binned_sah.h"
#include "model/bvh/intel_nodes.h"
#include "traces/error.h"
#include "traces/host_clock.h"

namespace rtsim {
namespace {

uint64_t align_up(uint64_t address, uint64_t align) {
  return (address + align - 1) / align * align;
}

// The first free address after an image, aligned for the next region.
uint64_t image_end(const BvhImage& image) {
  return align_up(image.end_address(), image.config.region_align);
}

void encode_instance_record(const InstanceRecord& r, uint8_t* out) {
  float xfm[12];
  for (int c = 0; c < 3; ++c)
    for (int row = 0; row < 3; ++row) xfm[c * 3 + row] = r.to_object.linear[c][row];
  for (int row = 0; row < 3; ++row) xfm[9 + row] = r.to_object.offset[row];
  std::memcpy(out, xfm, sizeof xfm);
  std::memcpy(out + 48, &r.blas, 4);
  std::memcpy(out + 52, &r.instance, 4);
  out[56] = r.mask;
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
  if (frame_tops)
    for (const BvhImage& t : *frame_tops) out.push_back(&t);
  if (bottom)
    for (const BvhImage& b : *bottom) out.push_back(&b);
  return out;
}

uint32_t BvhView::treelet_count() const {
  const BvhImage& last = *levels().back();
  return last.treelet_base + local_treelets(last);
}

uint32_t BvhView::root_treelet(uint32_t frame) const {
  return node_treelet(top_of(frame), 0);
}

std::vector<uint32_t> BvhView::root_treelets() const {
  std::vector<uint32_t> roots{root_treelet(0)};
  if (frame_tops)
    for (uint32_t f = 1; f <= frame_tops->size(); ++f) roots.push_back(root_treelet(f));
  return roots;
}

uint64_t BvhView::end_address() const {
  const BvhImage& last = bottom ? bottom->back() : *top;
  return last.end_address();
}

uint64_t BvhView::top_end_address() const {
  const BvhImage& last_top = frame_tops ? frame_tops->back() : *top;
  return bottom ? last_top.end_address() : top->node_base;
}

uint64_t TwoLevelBvh::total_bytes() const {
  uint64_t bytes = top.total_bytes();
  for (const BvhImage& t : frame_tops) bytes += t.total_bytes();
  for (const BvhImage& b : bottom) bytes += b.total_bytes();
  return bytes;
}

uint64_t TwoLevelBvh::node_count() const {
  uint64_t nodes = top.node_count;
  for (const BvhImage& t : frame_tops) nodes += t.node_count;
  for (const BvhImage& b : bottom) nodes += b.node_count;
  return nodes;
}

uint64_t TwoLevelBvh::triangle_count() const {
  if (bottom.empty()) return top.triangle_count;
  uint64_t triangles = 0;
  for (const BvhImage& b : bottom) triangles += b.triangle_count;
  return triangles;
}

uint32_t instance_record_bytes(NodeFormat format) {
  if (format == NodeFormat::Xe6) return kXeInstanceLeafBytes;
  return is_amd_format(format) ? kAmdInstanceBytes : kInstanceRecordBytes;
}

uint32_t instance_fetch_bytes(NodeFormat format) {
  return is_amd_format(format) ? kAmdInstanceFetchBytes : kInstanceRecordBytes;
}

InstanceRecord read_instance_record(const BvhImage& top, uint32_t position,
                                    const std::vector<BvhImage>* bottom) {
  const uint8_t* in = top.triangle_bytes(position);
  if (is_amd_format(top.config.node_format)) {
    if (!bottom) throw std::logic_error("read_instance_record: amd nodes need the bottom levels");
    return read_amd_instance(in, *bottom);
  }
  if (top.config.node_format == NodeFormat::Xe6) {  // the BLAS whose root the leaf points at
    uint64_t root;
    InstanceRecord r = decode_xe_instance(in, root);
    auto at = std::lower_bound(top.blas_roots.begin(), top.blas_roots.end(), root);
    r.blas = uint32_t(at - top.blas_roots.begin());
    return r;
  }
  float xfm[12];
  std::memcpy(xfm, in, sizeof xfm);
  InstanceRecord r;
  for (int c = 0; c < 3; ++c)
    for (int row = 0; row < 3; ++row) r.to_object.linear[c][row] = xfm[c * 3 + row];
  for (int row = 0; row < 3; ++row) r.to_object.offset[row] = xfm[9 + row];
  std::memcpy(&r.blas, in + 48, 4);
  std::memcpy(&r.instance, in + 52, 4);
  r.mask = in[56];
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
                               const BvhConfig& config, const BvhBuildStep& on_step,
                               const InstanceSettings& settings) {
  if (!settings.empty()) {
    if (config.instancing == Instancing::Flatten)
      throw_input_error("bvh.instancing", "",
                        "\"flatten\" (or --flatten) cannot keep the workload's instance masks or "
                        "motion (the stream's header sets them); use \"auto\" or \"two_level\"");
    return build_two_level_bvh(instances, config, on_step, settings);
  }
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

namespace {

// xe6: each top level's instance leaves get their BLAS's root address in place of its index.
void point_at_roots(TwoLevelBvh& bvh) {
  std::vector<uint64_t> roots;
  for (const BvhImage& b : bvh.bottom) roots.push_back(b.node_base);
  std::vector<BvhImage*> tops{&bvh.top};
  for (BvhImage& t : bvh.frame_tops) tops.push_back(&t);
  for (BvhImage* top : tops) {
    top->blas_roots = roots;
    // Leaf blocks come in whole instance leaves of two blocks.
    for (uint32_t p = 0; p < top->positions(); ++p) {
      if (top->holds_node(p)) continue;
      uint8_t* leaf = top->nodes.data() + size_t(p) * kXeBlockBytes;
      set_xe_instance_root(leaf, roots.at(xe_instance_root(leaf)));
      ++p;
    }
  }
}

// One frame's top level at `base`: one instance per leaf, so that each leaf is one transform.
BvhImage build_top_level(const std::vector<Instance>& instances,
                         const std::vector<Bounds>& mesh_boxes, BvhConfig config, uint64_t base,
                         const BvhBuildStep& on_step, TopLevelBuild& cost) {
  double start = wall_seconds();
  config.max_leaf_size = 1;
  config.node_base = base;
  std::vector<Bounds> boxes;
  std::vector<InstanceRecord> records;
  for (size_t i = 0; i < instances.size(); ++i) {
    const Instance& inst = instances[i];
    boxes.push_back(world_box(mesh_boxes[inst.mesh], inst.to_world));
    records.push_back({inverse(inst.to_world), inst.mesh, uint32_t(i), inst.mask, inst.to_world});
  }
  Bvh2 top2 = build_binned_sah(boxes, config);
  NodeFormat format = config.node_format;
  // xe6: the BLAS index stands in for its root address until point_at_roots.
  LeafRecords instance_records{instance_record_bytes(format),
                               [&](uint32_t prim, uint8_t* out) {
                                 if (is_amd_format(format))
                                   encode_amd_instance(records[prim], out);
                                 else if (format == NodeFormat::Xe6)
                                   encode_xe_instance(records[prim], records[prim].blas, out);
                                 else
                                   encode_instance_record(records[prim], out);
                               },
                               true};
  BvhImage top = encode_bvh_image(top2, config, instance_records, on_step);
  Bounds world;
  for (const Bounds& b : boxes) world.grow(b);
  set_scene_bounds(world, top);
  cost = {top.node_count, top.total_bytes(), wall_seconds() - start};
  return top;
}

}  // namespace

TwoLevelBvh build_two_level_bvh(const InstancedMesh& geometry, const BvhConfig& config,
                                const BvhBuildStep& on_step, const InstanceSettings& settings) {
  std::string problem = validate(config);
  if (!problem.empty()) throw_input_error("bvh config", "", problem);
  problem = instancing_problem(geometry);
  if (problem.empty()) problem = settings_problem(settings, geometry.instances.size());
  if (!problem.empty()) throw_input_error("instances", "", problem);
  TwoLevelBvh out;
  out.ray_masks = settings.ray_masks;
  std::vector<Bounds> mesh_boxes;
  for (const TriangleMesh& mesh : geometry.meshes) mesh_boxes.push_back(mesh_bounds(mesh));
  // Top levels, frame by frame, then the bottom levels, one after another in the address space.
  uint32_t frames = settings.animated() ? settings.frames : 1;
  uint64_t next = config.node_base;
  for (uint32_t f = 0; f < frames; ++f) {
    BvhImage top = build_top_level(instances_at(geometry.instances, settings, f), mesh_boxes,
                                   config, next, on_step, out.top_builds.emplace_back());
    next = image_end(top);
    if (f == 0) {
      out.top = std::move(top);
    } else {
      top.treelet_base = BvhView(out).treelet_count();
      out.frame_tops.push_back(std::move(top));
    }
  }
  for (const TriangleMesh& mesh : geometry.meshes) {
    BvhConfig bottom_config = config;
    bottom_config.node_base = next;
    uint32_t treelet_base = BvhView(out).treelet_count();
    out.bottom.push_back(build_bvh_image(mesh, bottom_config, on_step));
    out.bottom.back().treelet_base = treelet_base;
    next = image_end(out.bottom.back());
  }
  if (is_amd_format(config.node_format)) {
    link_amd_instances(out.top, out.bottom);
    for (BvhImage& top : out.frame_tops) link_amd_instances(top, out.bottom);
  }
  if (config.node_format == NodeFormat::Xe6) point_at_roots(out);
  return out;
}

}  // namespace rtsim
