// What one retired ray cost, added to its type's totals: the retire listeners of the sampled
// level's two methods (windows and scale model) both charge rays this way.
#pragma once

#include <algorithm>
#include <array>

#include "model/fidelity/fidelity_result.h"
#include "model/sched/ray_context.h"

namespace rtsim {

inline void charge_retired_ray(std::array<CostTotals, kRayTypeCount>& by_type,
                               const RayContext& ray, Cycle now) {
  CostTotals& c = by_type[int(ray.ray.type) % kRayTypeCount];
  c.rays++;
  c.nodes += ray.state.counters.trav_nodes;
  c.triangles += ray.state.counters.trav_prims;
  c.reads += ray.cost.reads;
  c.latency += double(now - std::min(now, ray.dispatched));
}

}  // namespace rtsim
