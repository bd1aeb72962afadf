#include "model/fidelity/functional_level.h"

#include "model/units/traversal.h"
#include "traces/stream.h"

namespace rtsim {

FidelityResult run_functional_level(BvhView image, const std::string& stream) {
  HostTimer timer;
  TraversalUnit unit(image, without_fetch_list());
  TraversalState state;
  std::array<CostTotals, kRayTypeCount> by_type{};
  RayStreamReader reader(stream);
  Ray ray;
  while (reader.next(ray)) {
    unit.trace(state, ray);
    CostTotals& t = by_type[int(ray.type) % kRayTypeCount];
    t.rays++;
    t.nodes += state.counters.trav_nodes;
    t.triangles += state.counters.trav_prims;
  }
  FidelityResult result;
  result.level = FidelityLevel::Functional;
  set_exact_estimates(result, by_type, {}, false);
  result.simulated_rays = result.rays;
  result.time_model = "none";
  timer.stop(result);
  return result;
}

}  // namespace rtsim
