// The per-ray traversal stack of an RT unit: `entries` on chip; deeper entries spill to memory.
// Timing assumptions: a step that pushes the on-chip stack past its depth writes the oldest
// entries out (one posted write per step, entry_bytes each, to the ray's spill region); a pop
// that finds the on-chip stack empty while entries are spilled reads back exactly what it needs
// (one read per step, which the step waits for). Spills live in local memory, cached like any
// data: in a region per ray slot of the unit (the next ray in the slot reuses it, as GPU local
// memory is reused), or, in treelet mode, where a ray moves between units, per ray context (its
// entry in the ray buffer). The region is fixed when the ray starts: a ray that packet
// reordering moves to another lane keeps its spilled entries where they are. The functional stack
// in TraversalState stays whole: this model only counts where its entries live and what moving them
// costs. Spill traffic as in Aila & Karras (HPG 2010), who name stack traffic the main auxiliary
// cost.
#pragma once

#include <cstdint>
#include <string>

#include "model/sched/ray_context.h"
#include "model/sched/stack_residency.h"

namespace rtsim {

struct StackConfig {
  uint32_t entries = 8;      // entries: depth of the on-chip stack per ray
  uint32_t entry_bytes = 8;  // bytes: one spilled entry (node reference + entry distance)
};

std::string stack_config_problem(const StackConfig& config);

// One transfer between the on-chip stack and memory; bytes = 0 means none.
struct StackTransfer {
  uint64_t addr = 0;
  uint32_t bytes = 0;
  uint32_t entries = 0;
};

class HardwareStack {
 public:
  // Spill regions: kRegionBytes each (entries wrap around within it).
  // Regions are one 64-byte line more than that apart: with a stride of exactly 4 KB the same
  // depth of every ray fell into the same few cache sets (1/64 of them with 64-byte lines),
  // and those sets thrashed.
  static constexpr uint64_t kSpillBase = kLocalMemoryBase;
  static constexpr uint64_t kRegionBytes = 4096;
  static constexpr uint64_t kRegionStride = kRegionBytes + 64;
  static uint64_t region(uint32_t context) { return kSpillBase + context * kRegionStride; }
  // Where entry `entry` of a context's stack spills to (entries wrap around within the region).
  static uint64_t entry_address(uint32_t context, uint32_t entry, uint32_t entry_bytes) {
    return region(context) + (uint64_t(entry) * entry_bytes) % kRegionBytes;
  }

  // slots_per_unit: regions per ray slot of a unit with that many slots; 0: per ray context.
  HardwareStack(const StackConfig& config, uint32_t slots_per_unit)
      : config_(config), slots_per_unit_(slots_per_unit) {}

  // A ray starts with its root entry on chip.
  void start(RayContext& ray) const {
    ray.residency = {};
    ray.stack_region = slots_per_unit_ ? ray.unit * slots_per_unit_ + ray.slot : ray.id;
  }
  // Before a step that pops `pops` entries: the read that brings back the spilled ones it
  // needs (none if the on-chip stack holds them).
  StackTransfer refill(RayContext& ray, uint32_t pops) const;
  // After a step: `kept` entries of the stack before it survive below `total` entries now;
  // returns the write that spills what no longer fits on chip.
  StackTransfer settle(RayContext& ray, uint32_t kept, uint32_t total) const;
  const StackConfig& config() const { return config_; }

 private:
  uint64_t address(const RayContext& ray, uint32_t entry) const {
    return entry_address(ray.stack_region, entry, config_.entry_bytes);
  }
  StackConfig config_;
  uint32_t slots_per_unit_;
};

}  // namespace rtsim
