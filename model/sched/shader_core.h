// The shader side of an RT unit: the SM whose warps call trace and shade what comes back
// (`[shader] model = "simt"`; with "none" the unit takes rays straight from the dispatcher).
// A ShaderCore sits between the unit and its ray supply, one per unit (an SM and its RT core):
//  - a warp the unit takes is a shader warp: it needs a free warp slot of the SM (`warps`);
//    with none free the unit gets no rays ("not now") and is woken when one frees;
//  - ray generation: the warp occupies one of the SM's warp schedulers for the raygen cycles of
//    each ray type it holds (SIMT: diverging types run one after the other); its rays reach the
//    unit `trace_latency` cycles after that (or when the dispatcher delivers them, if later);
//  - the warp waits for its slowest ray; `trace_latency` cycles after its last ray retires it
//    shades: hit cycles of each type with a hit plus miss cycles of each type with a miss (a
//    warp with hits and misses runs both shaders), on the first free scheduler;
//  - shading reads `bytes_per_hit` for each hit (G-buffer, textures, payload) at the ray's
//    pixel's address in the shading region (shading_address) through the unit's L1, so they
//    compete with BVH traffic in the L1, L2 and DRAM. They are issued when the warp's last ray
//    retires (a unit's reads go out in its local time order), so the hand-off back to the SM
//    hides up to trace_latency of their latency, and the shading cycles overlap the rest;
//  - the warp's slot frees when its shading cycles are done and its reads are back.
// Schedulers are booked in the order the unit asks (its local time order): ray generation
// asked for later than a shading booked ahead of it queues behind it (an approximation; the
// idle gap before that shading is lost). Needs whole warps:
// depth-first traversal refilled by warp, or packet traversal (treelet queues move rays
// between units, so a warp's rays would not come back to its SM).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "model/mem/memory_level.h"
#include "model/sched/ray_supply.h"

namespace rtsim {

enum class ShaderModel : uint8_t { None, Simt };
const char* shader_model_name(ShaderModel model);  // none, simt

// Scheduler cycles one warp spends in each shader of a ray type.
struct ShaderCycles {
  uint32_t raygen = 0, hit = 0, miss = 0;
};

struct ShaderConfig {
  ShaderModel model = ShaderModel::None;
  uint32_t warps = 48;          // warp slots of the SM
  uint32_t schedulers = 4;      // warp schedulers: each issues one warp instruction a cycle
  uint32_t trace_latency = 20;  // cycles: each way between the SM and its RT unit
  uint32_t bytes_per_hit = 64;  // bytes: what hit shading reads per hit
  std::array<ShaderCycles, kRayTypeCount> cycles = default_shader_cycles();

  static std::array<ShaderCycles, kRayTypeCount> default_shader_cycles();
};

std::string shader_config_problem(const ShaderConfig& config);

// Where hit shading reads for a ray of `pixel` in `frame`: per pixel in the shading region
// (kShadingBase), a new range each frame (the raster pass rewrote the G-buffer), wrapping
// within the region.
uint64_t shading_address(uint32_t frame, uint32_t pixel, uint32_t bytes_per_hit);

struct ShaderStats {
  uint64_t warps = 0, rays = 0, hits = 0;
  uint64_t raygen_cycles = 0, hit_cycles = 0, miss_cycles = 0;  // scheduler cycles booked
  std::array<uint64_t, kRayTypeCount> type_cycles{};            // scheduler cycles per ray type
  uint64_t trace_delay_cycles = 0;  // sum over rays: how much later ray generation made them
  uint64_t slot_waits = 0;          // times the unit found no warp slot free
  uint64_t slot_wait_cycles = 0;    // cycles it then waited for one
  std::array<ReadCounts, kRayTypeCount> reads{};  // the shading reads, by the hit ray's type
  uint64_t read_bytes = 0;
  Cycle last_cycle = 0;  // the last warp slot freed
  uint64_t busy_cycles() const { return raygen_cycles + hit_cycles + miss_cycles; }
  ShaderStats& operator+=(const ShaderStats& o);  // sums; last_cycle: the later
};

class ShaderCore : public RaySupply, private ReadClient {
 public:
  // upstream: where rays come from; memory: the unit's L1; wake(cycle): a warp slot frees at
  // cycle while the unit waits for one (the SystemC wrapper wakes the unit then).
  ShaderCore(const ShaderConfig& config, RaySupply& upstream, MemoryTarget& memory,
             std::function<void(Cycle)> wake);

  size_t take(uint32_t unit, Cycle now, size_t max, std::vector<RayContext*>& out) override;
  void retire(RayContext& ray, Cycle now) override;
  // Exhausted once the stream is and every warp's shading reads are back.
  bool exhausted() const override { return upstream_.exhausted() && shading_reads_ == 0; }

  const ShaderStats& stats() const { return stats_; }
  const ShaderConfig& config() const { return config_; }
  // While the unit waits for a warp slot, or, the stream exhausted, for the last warps to
  // finish shading: the first cycle from `now` on that a warp frees (kPending: none known, or
  // the unit does not wait), for the stall watchdog.
  Cycle next_wake(Cycle now) const;
  std::string dump() const;

 private:
  struct Warp {
    Cycle free_at = 0;  // kPending while tracing or waiting for reads
    uint32_t tracing = 0, pending_reads = 0;
    uint32_t miss_types = 0;  // bit per ray type with a miss (hits: the types in `hits`)
    Cycle shaded = 0;         // end of its shading cycles, and of its reads once back
    struct HitRay {
      uint32_t pixel, frame;
      RayType type;
    };
    std::vector<HitRay> hits;
  };
  // Books `cycles` on the first free scheduler from `at`; returns the end.
  Cycle occupy(Cycle at, uint64_t cycles);
  uint64_t cycles_of(uint32_t types, uint32_t ShaderCycles::*phase, uint64_t& phase_total);
  void shade(uint32_t warp, Cycle now);
  void read_done(uint64_t warp, Cycle ready, const ReadCharge& charge) override;
  void free_slot(uint32_t warp);

  ShaderConfig config_;
  RaySupply& upstream_;
  MemoryTarget& memory_;
  std::function<void(Cycle)> wake_;
  std::vector<Warp> warps_;
  std::vector<Cycle> scheduler_free_;
  uint32_t shading_reads_ = 0;      // warps whose shading reads are not all back
  Cycle starved_since_ = kPending;  // the unit asked and found no warp slot
  ShaderStats stats_;
};

}  // namespace rtsim
