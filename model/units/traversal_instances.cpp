// The two-level part of the traversal unit (traversal.h): instance steps and the way back to
// world space. In a file of its own, so that the single-level loop compiles as it did.
#include <algorithm>
#include <cmath>

#include "model/units/traversal.h"

namespace rtsim {

StepResult TraversalUnit::visit_instance(TraversalState& s, const StackEntry& entry) const {
  StepResult out{StepKind::Instance, static_cast<uint32_t>(s.accesses.size()), 0, 1, 0};
  // Fetch the instance record.
  out.fetch_address = s.top->triangle_address(entry.index);
  out.fetch_bytes = instance_fetch_bytes(s.top->config.node_format);
  if (config_.record_accesses) {
    record(s, out.fetch_address, out.fetch_bytes, AccessKind::Instance);
    out.access_count = 1;
  }
  InstanceRecord r = read_instance_record(*s.top, entry.index, bvh_.bottom);
  if ((r.mask & s.mask) == 0) {
    out.tests = 0;
    return out;
  }
  s.counters.trav_instances++;
  const BvhImage& blas = (*bvh_.bottom)[r.blas];
  // Transform the ray into object space, in the world ray's t units, and enter the BLAS root;
  // the marker below its entries brings the ray back.
  Ray object;
  object.org = r.to_object.point(s.ray.org);
  object.dir = r.to_object.vector(s.ray.dir);
  object.tmin = s.ray.tmin;
  object.tmax = s.t_hit;
  s.world = s.ray;
  s.world_t_hit = s.t_hit;
  s.ray = prepare_ray(object, blas.scene_extent, config_.box_padding);
  s.ray.t_limit = std::min(s.ray.t_limit, std::ldexp(s.world.t_limit, -s.ray.t_exponent));
  s.t_hit = s.ray.tmax;
  s.level = &blas;
  s.instance = r.instance;
  s.stack.push_back({0, kLeaveInstance, 0.0f});
  s.stack.push_back({0, 0, s.ray.tmin});
  if (s.stack.size() > s.max_stack) s.max_stack = static_cast<uint32_t>(s.stack.size());
  return out;
}

float TraversalUnit::world_t_hit(const TraversalState& s) {
  // A hit in the instance moves t (object t is world t scaled by a power of two in prepare_ray:
  // exact); without one, the world's t stands as it was, also where the scaling overflowed.
  bool hit_here = s.hit_instance == s.instance;  // each instance is entered at most once
  return hit_here ? std::ldexp(s.t_hit, s.ray.t_exponent) : s.world_t_hit;
}

void TraversalUnit::leave_instance(TraversalState& s) const {
  s.t_hit = world_t_hit(s);
  s.ray = s.world;
  s.level = s.top;
  s.instance = kNoHit;
}

}  // namespace rtsim
