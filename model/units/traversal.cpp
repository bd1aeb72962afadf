#include "model/units/traversal.h"

#include <algorithm>
#include <cmath>

#include "model/bvh/node_format.h"
#include "model/mem/memory_level.h"
#include "model/units/ray_box.h"
#include "model/units/ray_triangle.h"

namespace rtsim {

TraversalCounters& TraversalCounters::operator+=(const TraversalCounters& o) {
  trav_nodes += o.trav_nodes;
  trav_leaves += o.trav_leaves;
  trav_prims += o.trav_prims;
  trav_prim_hits += o.trav_prim_hits;
  trav_alpha_tests += o.trav_alpha_tests;
  trav_instances += o.trav_instances;
  return *this;
}

void TraversalUnit::record(TraversalState& s, uint64_t address, uint32_t bytes, AccessKind kind) {
  MemoryAccess& access = s.accesses.emplace_back();
  access.address = address;
  access.bytes = bytes;
  access.kind = kind;
}

TraversalUnit::TraversalUnit(BvhView bvh, TraversalConfig config) : bvh_(bvh), config_(config) {}

void TraversalUnit::begin(TraversalState& s, const Ray& ray) const {
  s.top = &bvh_.top_of(ray.frame);
  s.mask = bvh_.ray_mask(ray.type);
  s.ray = prepare_ray(ray, s.top->scene_extent, config_.box_padding);
  s.query = ray.query;
  s.force_opaque = ray.force_opaque;
  s.t_hit = s.ray.tmax;
  s.prim = kNoHit;
  s.u = s.v = 0.0f;
  s.level = s.top;
  s.instance = s.hit_instance = kNoHit;
  s.stack.clear();
  s.stack.push_back({0, 0, s.ray.tmin});
  s.max_stack = 1;
  s.counters = {};
  s.accesses.clear();
  s.texels.clear();
  s.done = false;
}

StepResult TraversalUnit::step(TraversalState& s) const {
  // Pop until an entry that may still hold a closer hit; none left means the ray is done.
  while (!s.stack.empty()) {
    StackEntry entry = s.stack.back();
    s.stack.pop_back();
    if (entry.count == kLeaveInstance) {
      leave_instance(s);
      continue;
    }
    if (entry.tnear > s.t_hit * kSlabFarGrowth) continue;
    switch (kind_of(entry, s.level == s.top)) {
      case StepKind::Node: return visit_node(s, entry);
      case StepKind::Instance: return visit_instance(s, entry);
      default: return visit_leaf(s, entry);
    }
  }
  s.done = true;
  return {};
}

void TraversalUnit::prime(const TraversalState& s) const {
  if (s.stack.empty() || s.stack.back().count == kLeaveInstance) return;
  const StackEntry& top = s.stack.back();
  const BvhImage& level = *s.level;
  constexpr size_t kMostBytes = 512;  // a wide node, or a leaf of a few triangles
  StepKind kind = kind_of(top, s.level == s.top);
  if (kind == StepKind::Node)
    prefetch_span(level.node_bytes(top.index), std::min<size_t>(level.node_size, kMostBytes), 64);
  else if (kind == StepKind::Leaf)
    prefetch_span(level.triangle_bytes(top.index),
                  std::min<size_t>(size_t(top.count) * level.triangle_stride, kMostBytes), 64);
}

StepResult TraversalUnit::visit_node(TraversalState& s, const StackEntry& entry) const {
  const BvhImage& level = *s.level;
  StepResult out{StepKind::Node, static_cast<uint32_t>(s.accesses.size()), 0, 0, 0};
  // Fetch the node.
  s.counters.trav_nodes++;
  out.fetch_address = level.node_address(entry.index);
  out.fetch_bytes = level.node_size;
  if (config_.record_accesses) {
    record(s, out.fetch_address, level.node_size, AccessKind::Node);
    out.access_count = 1;
  }
  NodeView node;
  decode_node(level.config.node_format, level.config.width, level.node_bytes(entry.index), node,
              entry.index, level.regions());
  // Test every child box.
  float tnear[kMaxWidth];
  uint32_t hits = intersect_children(s.ray, node, s.t_hit, tnear);
  out.tests = count_bits(node.valid);
  out.hits = count_bits(hits);
  // Sort the hit children near to far.
  float dist[kMaxWidth];
  int slot_of[kMaxWidth];
  int n = 0;
  for (uint32_t left = hits; left != 0; left &= left - 1) {
    int slot = __builtin_ctz(left);
    int i = n++;
    while (i > 0 && dist[i - 1] > tnear[slot]) {
      dist[i] = dist[i - 1];
      slot_of[i] = slot_of[i - 1];
      --i;
    }
    dist[i] = tnear[slot];
    slot_of[i] = slot;
  }
  // Push far to near, so the nearest child is visited next.
  for (int i = n - 1; i >= 0; --i) {
    int slot = slot_of[i];
    s.stack.push_back({node.index[slot], node.count[slot], dist[i]});
  }
  if (s.stack.size() > s.max_stack) s.max_stack = static_cast<uint32_t>(s.stack.size());
  return out;
}

StepResult TraversalUnit::visit_leaf(TraversalState& s, const StackEntry& entry) const {
  const BvhImage& level = *s.level;
  StepResult out{StepKind::Leaf, static_cast<uint32_t>(s.accesses.size()), 0, 0, 0};
  s.counters.trav_leaves++;
  out.fetch_address = level.triangle_address(entry.index);
  TriangleFormat format = level.config.triangle_format;
  uint32_t records = 0;
  bool answered = false;
  for (uint32_t i = 0; i < entry.count && !answered; ++i) {
    // Fetch the record (a triangle; an xe_quad: one or two) and test its triangles against the
    // range still open.
    uint32_t position = entry.index + i;
    const uint8_t* bytes = level.triangle_bytes(position);
    records++;
    if (config_.record_accesses) {
      record(s, level.triangle_address(position), level.triangle_stride, AccessKind::Triangle);
      out.access_count++;
    }
    uint32_t parts = format == TriangleFormat::XeQuad ? xe_quad_triangles(bytes) : 1;
    for (uint32_t part = 0; part < parts; ++part) {
      s.counters.trav_prims++;
      out.tests++;
      TriangleHit hit;
      uint32_t prim;
      if (!intersect_triangle(format, s.ray, bytes, part, s.ray.tmin,
                              std::min(s.t_hit, s.ray.t_limit), hit, prim))
        continue;
      if (level.alpha && !s.force_opaque && level.alpha->tested(prim)) {
        s.counters.trav_alpha_tests++;
        out.anyhit_calls++;
        TriangleAlpha::Lookup texel = level.alpha->look_up(prim, hit.u, hit.v);
        s.texels.push_back(kTextureBase + texel.texel_offset);
        if (!texel.opaque) continue;
      }
      // Keep the hit; the range now ends there.
      s.counters.trav_prim_hits++;
      out.hits++;
      s.t_hit = hit.t;
      s.prim = prim;
      s.hit_instance = s.instance;
      s.u = hit.u;
      s.v = hit.v;
      // An any-hit query is answered by its first hit (and ends in world space).
      if (s.query == Query::AnyHit) {
        if (s.instance != kNoHit) leave_instance(s);
        s.stack.clear();
        answered = true;
        break;
      }
    }
  }
  out.fetch_bytes = records * level.triangle_stride;  // the records tested, in order
  return out;
}

Hit TraversalUnit::result(const TraversalState& s, const Ray& ray) const {
  Hit hit;
  if (s.prim == kNoHit) return hit;
  if (s.query == Query::AnyHit) {
    hit.t = ray.tmax;
    hit.prim = kAnyPrim;
    return hit;
  }
  hit.t = s.ray.t_exponent == 0 ? s.t_hit : std::ldexp(s.t_hit, s.ray.t_exponent);
  hit.u = s.u;
  hit.v = s.v;
  hit.prim = s.prim;
  hit.instance = s.hit_instance;
  return hit;
}

Hit TraversalUnit::trace(TraversalState& s, const Ray& ray) const {
  begin(s, ray);
  while (step(s).kind != StepKind::Done) {
  }
  return result(s, ray);
}

}  // namespace rtsim
