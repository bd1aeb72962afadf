#include "model/fidelity/cycle_level.h"

#include <cstdlib>

#include "model/fidelity/cache_hierarchy.h"
#include "model/sched/ray_source.h"
#include "traces/stream.h"

namespace rtsim {

FidelityResult cycle_level_result(const RtSimulator& sim) {
  std::array<CostTotals, kRayTypeCount> by_type{};
  // A shader model's shading reads count with the traffic of the rays whose hits they shade.
  std::array<ReadCounts, kRayTypeCount> shading = sim.shading_reads();
  for (int t = 0; t < kRayTypeCount; ++t) {
    const RayTypeStats& s = sim.collected().by_type()[t];
    CostTotals& c = by_type[t];
    c.rays = s.rays;
    c.nodes = s.counters.trav_nodes;
    c.triangles = s.counters.trav_prims;
    c.reads += s.reads;
    c.reads += shading[t];
    c.latency = s.latency.mean() * double(s.latency.count());
  }
  FidelityResult result;
  result.level = FidelityLevel::Cycle;
  result.clock_ghz = sim.config().clock_ghz;
  set_exact_estimates(result, by_type, level_names(sim.config().memory), true);
  result.simulated_rays = result.rays;
  result.cycles = Estimate::exact(double(sim.cycles()));
  result.time_model = "cycle-approximate model";
  return result;
}

FidelityResult run_cycle_level(const HwConfig& config, BvhView image, const std::string& stream) {
  setenv("SYSC_DISABLE_COPYRIGHT_MESSAGE", "1", 1);
  HostTimer timer;
  RayStreamReader reader(stream);
  StreamRaySource source(reader);
  RtSimulator sim(config, image, source);
  sim.run();
  FidelityResult result = cycle_level_result(sim);
  timer.stop(result);
  return result;
}

}  // namespace rtsim
