// The warmed scale model's ray source (model/fidelity/README.md, "Warmed"): it hands out the
// sampled warps' rays, and before each sampled warp it traces the warps not drawn since the
// previous one functionally on the full machine's other (absent) RT units, so that the scale
// model's L2 holds what the full machine's would.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "model/bvh/two_level.h"
#include "model/config/hw_config.h"
#include "model/fidelity/ray_range_reader.h"
#include "model/sc/rt_simulator.h"
#include "model/sched/ray_source.h"
#include "model/units/traversal.h"

namespace rtsim {

// An absent unit's L1 as a filter of its reads: tags only (a line's sectors present or not),
// LRU within a set, no timing and no writes. What it misses goes to the L2.
class L1Filter {
 public:
  explicit L1Filter(const CacheConfig& config);
  // Calls miss(addr, bytes) for each sector of [addr, addr + bytes) it did not hold.
  template <class Miss>
  void read(uint64_t addr, uint32_t bytes, Miss miss);

 private:
  // The set's lines in recency order (most recent first); bit s of sectors: sector s present.
  struct Line {
    uint64_t line = ~uint64_t(0);
    uint32_t sectors = 0;
  };
  Line& find(uint64_t line);  // moves it to the front, or evicts the last way for it
  uint32_t ways_, sets_, line_shift_, sector_shift_;
  std::vector<Line> lines_;
};

// The sampled warps' rays in stream order; with warm(sim), before each warp is handed out, the
// warps not drawn since the previous one run on the absent units: warp w on absent unit w mod
// their count (its L1Filter), its rays' stacks spilling as HardwareStack spills them to that
// unit's ray slots, and what the filters miss, and the spills and refills, reach sim's L2 through
// RtSimulator::warm_l2, all of a warp's reads at the moment it is warmed.
class WarmingSource : public RaySource {
 public:
  // rays: the sampled warps' rays (warps: their indices, unit: rays per warp); reader: the
  // stream, for the others; full: the machine the scale model stands in for; scaled: the model.
  WarmingSource(const std::vector<Ray>& rays, const std::vector<uint64_t>& warps, uint64_t unit,
                RayRangeReader& reader, BvhView image, const HwConfig& full,
                const HwConfig& scaled);

  void warm(RtSimulator& sim);
  // Blocks the absent units fetched into the L2, by the type of the ray that read them.
  const std::array<double, kRayTypeCount>& fetched() const { return fetched_; }

  bool next(Ray& ray) override;

 private:
  void warm_until(uint64_t warp);
  // Returns the blocks the ray's reads fetched into the L2.
  uint32_t trace(const Ray& ray, L1Filter& l1, uint32_t context);  // context: its spill region

  const std::vector<Ray>& rays_;
  const std::vector<uint64_t>& warps_;
  uint64_t unit_;
  RayRangeReader& reader_;
  TraversalUnit traversal_;
  StackConfig stack_;
  uint64_t warps_per_unit_, warp_size_, own_slots_;
  CacheConfig filter_;  // the absent units' first level, as their filters
  uint32_t absent_units_;
  std::vector<L1Filter> l1s_;  // the absent units', from warm()
  RtSimulator* sim_ = nullptr;
  size_t position_ = 0;
  uint64_t next_warp_ = 0;
  std::vector<Ray> others_;
  TraversalState state_;
  std::array<double, kRayTypeCount> fetched_{};
};

}  // namespace rtsim
