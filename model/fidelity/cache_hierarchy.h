// The machine's cache levels ([[memory.level]], model/mem/hierarchy.h) as plain caches that
// answer at once, for the cache fidelity level's walk and the curve's pass (no SystemC, no
// queues): each level has its instances as the cycle model builds them (one per unit, one per
// group of N units in unit order, or one shared), each instance its address-hashed slices
// (model/mem/slice_hash.h, as model/sc/shared_levels_module.h places lines), and a level's misses,
// write-backs and clean evictions (to a victim level, Cache::fill) go to the instance of the
// next level that serves the same units, or to DRAM after the last. Every Cache has its place
// (cache_place), so a read's ReadCharge counts each level's accesses and hits as the cycle
// model's do.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "model/config/hw_config.h"
#include "model/mem/cache.h"

namespace rtsim {

// What arrives at a level's instance: a read of a block (a miss of the level above, or the
// unit's own read at the first level), a write (a write-back or a write-through), or a clean
// line the level above evicted (to a victim level).
enum class LevelReference : uint8_t { Read, Write, Fill };

// Sees the references arriving at one level, block by block (the level's block: its sector, or
// its line), in the order they arrive, with the instance they arrive at.
class LevelReferenceSink {
 public:
  virtual ~LevelReferenceSink() = default;
  virtual void reference(uint32_t instance, uint64_t addr, LevelReference kind) = 0;
};

// The names of the levels, from the unit outwards.
std::vector<std::string> level_names(const std::vector<MemoryLevelConfig>& levels);

class CacheHierarchy {
 public:
  // levels: as built (levels_as_built); units: RT units; dram: below the last level. With a
  // sink, the references arriving at level `tapped` are told to it.
  CacheHierarchy(const std::vector<MemoryLevelConfig>& levels, uint32_t units, MemoryTarget& dram,
                 LevelReferenceSink* sink = nullptr, uint32_t tapped = 0);
  ~CacheHierarchy();
  CacheHierarchy(const CacheHierarchy&) = delete;
  CacheHierarchy& operator=(const CacheHierarchy&) = delete;

  // What unit `unit` reads and writes: its instance of the first level.
  MemoryTarget& unit(uint32_t unit);
  uint32_t levels() const { return uint32_t(levels_.size()); }
  uint32_t instances(uint32_t level) const;
  // Level `level`'s counters, summed over its instances and slices.
  CacheStats stats(uint32_t level) const;

 private:
  class Instance;
  std::vector<MemoryLevelConfig> levels_;
  std::vector<std::vector<std::unique_ptr<Instance>>> instances_;  // per level
};

}  // namespace rtsim
