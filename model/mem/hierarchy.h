// The cache levels of a machine, from the RT unit outwards ([[memory.level]] in a hardware
// config; model/SIM.md, "The memory hierarchy"). Each level is a cache config, a scope (how
// many instances there are and who shares each), how it is filled, its slices and the link to
// the level below it. The first level is the unit's own (the unit reads it by call); levels
// shared by several units serve their requests in time order (model/sc/shared_levels_module.h);
// the last level's misses go to DRAM.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "model/mem/cache.h"
#include "model/mem/crossbar.h"

namespace rtsim {

// unit: one per RT unit; group: one per `group` units (in unit order); shared: one.
enum class LevelScope : uint8_t { Unit, Group, Shared };
// miss: a read miss fetches the block (and holds an MSHR); victim: the level above's evicted
// lines fill it (Infinity-Cache-like), its read misses go below without taking a line.
enum class LevelFill : uint8_t { Miss, Victim };

struct MemoryLevelConfig {
  std::string name;  // its stats are mem.NAME.*; its keys memory.NAME.*
  LevelScope scope = LevelScope::Unit;
  uint32_t group = 1;  // units per instance (scope group)
  LevelFill fill = LevelFill::Miss;
  CacheConfig cache;    // of one instance, all its slices together
  uint32_t slices = 1;  // address-hashed slices of a shared or group level
  CrossbarConfig link;  // from each instance of this level to the next level's slices, each way
};

// The level's instances on a machine of `units` RT units, and how many units share one.
uint32_t units_per_instance(const MemoryLevelConfig& level, uint32_t units);
uint32_t level_instances(const MemoryLevelConfig& level, uint32_t units);
// Whether the level serves several requesters in time order (a group or shared level), rather
// than being part of one unit.
inline bool queued_level(const MemoryLevelConfig& level) {
  return level.scope != LevelScope::Unit;
}
// How many levels, from the first, are each unit's own (the rest are group or shared levels).
uint32_t own_levels(const std::vector<MemoryLevelConfig>& levels);
// "unit", "group:4", "shared".
std::string scope_name(const MemoryLevelConfig& level);
// Parses a scope name into level; false if it is not one.
bool parse_scope(const std::string& text, MemoryLevelConfig& level);

// Why the hierarchy cannot be built (empty if fine), naming the level ("[memory.l2] ...").
std::string hierarchy_problem(const std::vector<MemoryLevelConfig>& levels);

// A level's place in the hierarchy for its caches (counters, fill, victims below).
CachePlace cache_place(const std::vector<MemoryLevelConfig>& levels, uint32_t index);

}  // namespace rtsim
