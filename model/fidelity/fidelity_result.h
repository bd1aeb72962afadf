// What every fidelity level of the hardware model reports, in one shape, so levels can be
// compared with the full cycle-approximate run (rtsim speed-vs-error) and shown in reports.
// A level that does not model a quantity leaves it unknown (functional: no cycles, no caches).
// Exact levels report totals with a zero confidence interval; the sampled level reports
// estimates with the half-width of their 95% confidence interval.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/mem/memory_level.h"
#include "traces/ray.h"

namespace rtsim {

// From fastest to most detailed: traversal counts only; counts plus the cache hierarchy and an
// analytic time; the full cycle-approximate SystemC model; the full model on a sample of rays.
enum class FidelityLevel : uint8_t { Functional, CacheLevel, Cycle, Sampled };

const char* fidelity_level_name(FidelityLevel level);  // functional, cache, cycle, sampled
std::optional<FidelityLevel> fidelity_level_from_name(const std::string& name);

struct Estimate {
  bool known = false;  // false: the level does not model this quantity
  double value = 0;
  double ci95 = 0;  // half-width of the 95% confidence interval; 0 for exact levels

  static Estimate exact(double v) { return {true, v, 0.0}; }
};

// What a set of rays cost: plain sums, ratios derived when read.
struct CostTotals {
  uint64_t rays = 0, nodes = 0, triangles = 0;
  ReadCounts reads;    // per cache level, from the unit's first (0) to the level above DRAM
  double latency = 0;  // sum of ray latencies, cycles (timed levels only)

  CostTotals& operator+=(const CostTotals& o);
};

// One cache level's hit rate ([[memory.level]] name, model/mem/hierarchy.h).
struct LevelEstimate {
  std::string name;
  Estimate hit_rate;
};

// The hit rates of the cache levels from the unit outwards (empty: caches not modelled).
using LevelEstimates = std::vector<LevelEstimate>;
// The unit's first level's and the level above DRAM's (the same in a one-level hierarchy);
// unknown when there are none.
Estimate first_level_hit_rate(const LevelEstimates& levels);
Estimate last_level_hit_rate(const LevelEstimates& levels);

struct TypeEstimate {
  uint64_t rays = 0;  // rays of this type in the stream (exact)
  Estimate nodes_per_ray, triangles_per_ray, dram_bytes_per_ray;
  LevelEstimates levels;
  Estimate latency_mean;
  Estimate first_level_hit_rate() const { return rtsim::first_level_hit_rate(levels); }
  Estimate last_level_hit_rate() const { return rtsim::last_level_hit_rate(levels); }
};

struct FidelityResult {
  FidelityLevel level = FidelityLevel::Cycle;
  uint32_t sample_rate = 1;     // sampled level: 1 in sample_rate rays measured
  std::string sample_method;    // sampled level: scale-model or windows; empty otherwise
  uint64_t rays = 0;            // rays in the stream
  uint64_t simulated_rays = 0;  // rays the level processed, warm-up included
  uint64_t measured_rays = 0;   // rays whose costs went into the estimates
  uint32_t strata = 0;          // sampled level: strata (one measured window or warp each)
  double clock_ghz = 1.0;
  std::string time_model;  // how cycles were obtained (cache level: the binding bound)
  std::string caveat;      // sampled level: why estimates may be biased, if it is known (or empty)
  Estimate cycles, dram_bytes, nodes_per_ray, triangles_per_ray;
  LevelEstimates levels;  // each cache level's hit rate
  std::array<TypeEstimate, kRayTypeCount> types;
  double host_seconds = 0;  // wall time of the level's run, scene and BVH excluded
  double cpu_seconds = 0;   // CPU time of the same (steadier on a busy machine)

  double mrays_per_second() const;
  Estimate first_level_hit_rate() const { return rtsim::first_level_hit_rate(levels); }
  Estimate last_level_hit_rate() const { return rtsim::last_level_hit_rate(levels); }
  nlohmann::ordered_json to_json() const;
  static FidelityResult from_json(const nlohmann::json& doc);
};

// Wall and CPU time of this process since construction.
class HostTimer {
 public:
  HostTimer();
  void stop(FidelityResult& result) const;  // sets host_seconds and cpu_seconds

 private:
  double wall_, cpu_;
};

// Fills the ray-count-derived estimates of a result from exact totals per ray type.
// timed: latency sums are meaningful; levels: the names of the cache levels whose counters are
// meaningful (reads level i is levels[i]), none for a level without caches or DRAM.
void set_exact_estimates(FidelityResult& result,
                         const std::array<CostTotals, kRayTypeCount>& by_type,
                         const std::vector<std::string>& levels, bool timed);

}  // namespace rtsim
