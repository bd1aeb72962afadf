#include "model/mem/hierarchy.h"

#include <algorithm>

#include <fmt/format.h>

namespace rtsim {

uint32_t units_per_instance(const MemoryLevelConfig& level, uint32_t units) {
  switch (level.scope) {
    case LevelScope::Unit: return 1;
    case LevelScope::Group: return std::min(level.group, std::max(units, 1u));
    case LevelScope::Shared: break;
  }
  return std::max(units, 1u);
}

uint32_t level_instances(const MemoryLevelConfig& level, uint32_t units) {
  uint32_t per = units_per_instance(level, units);
  return (std::max(units, 1u) + per - 1) / per;
}

uint32_t own_levels(const std::vector<MemoryLevelConfig>& levels) {
  uint32_t own = 0;
  while (own < levels.size() && !queued_level(levels[own])) ++own;
  return own;
}

std::string scope_name(const MemoryLevelConfig& level) {
  switch (level.scope) {
    case LevelScope::Unit: return "unit";
    case LevelScope::Group: return fmt::format("group:{}", level.group);
    case LevelScope::Shared: break;
  }
  return "shared";
}

bool parse_scope(const std::string& text, MemoryLevelConfig& level) {
  if (text == "unit" || text == "shared") {
    level.scope = text == "unit" ? LevelScope::Unit : LevelScope::Shared;
    level.group = 1;
    return true;
  }
  const std::string prefix = "group:";
  if (text.compare(0, prefix.size(), prefix) != 0 || text.size() == prefix.size() ||
      text.size() > prefix.size() + 4)
    return false;
  uint32_t n = 0;
  for (char c : text.substr(prefix.size())) {
    if (c < '0' || c > '9') return false;
    n = n * 10 + uint32_t(c - '0');
  }
  if (n < 1 || n > 1024) return false;
  level.scope = LevelScope::Group;
  level.group = n;
  return true;
}

namespace {

bool valid_name(const std::string& name) {
  if (name.empty() || name.size() > 32 || name == "levels" || !(name[0] >= 'a' && name[0] <= 'z'))
    return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
  });
}

// Why level i cannot follow level i - 1 (empty if it can).
std::string order_problem(const MemoryLevelConfig& above, const MemoryLevelConfig& level) {
  if (!queued_level(above)) {
    if (above.link.latency != 0 || above.link.bytes_per_cycle != 0) {
      if (!queued_level(level))
        return fmt::format(
            "a unit's own levels are joined directly: memory.{}.link_latency and "
            "link_bytes_per_cycle must be 0 (give the latency in hit_latency)",
            above.name);
    }
    return {};
  }
  if (!queued_level(level))
    return fmt::format("scope unit cannot follow {} (memory.{}): sharing grows outwards",
                       scope_name(above), above.name);
  if (above.scope == LevelScope::Shared && level.scope == LevelScope::Group)
    return fmt::format("scope {} cannot follow shared (memory.{}): sharing grows outwards",
                       scope_name(level), above.name);
  if (above.scope == LevelScope::Group && level.scope == LevelScope::Group &&
      level.group % above.group != 0)
    return fmt::format("its group ({}) must be a multiple of memory.{}'s ({})", level.group,
                       above.name, above.group);
  return {};
}

std::string level_problem(const std::vector<MemoryLevelConfig>& levels, size_t i) {
  const MemoryLevelConfig& level = levels[i];
  std::string p = cache_config_problem(level.cache);
  if (!p.empty()) return p;
  if (!queued_level(level) && level.slices != 1)
    return "slices: a unit's own level has one (slices are for group and shared levels)";
  p = slice_layout_problem(level.cache, {level.slices, level.link});
  if (!p.empty()) return p;
  if (i + 1 == levels.size() && (level.link.latency != 0 || level.link.bytes_per_cycle != 0))
    return "the last level has no link below: the DRAM model times its channel "
           "(link_latency and link_bytes_per_cycle must be 0)";
  if (i == 0) {
    if (level.scope != LevelScope::Unit)
      return "the first level is the RT unit's own: scope must be \"unit\"";
    if (level.fill == LevelFill::Victim) return "the first level is filled by its misses";
    return {};
  }
  const MemoryLevelConfig& above = levels[i - 1];
  p = order_problem(above, level);
  if (!p.empty()) return p;
  if (level.fill == LevelFill::Victim && (level.cache.line_bytes != above.cache.line_bytes ||
                                          block_bytes(level.cache) != block_bytes(above.cache)))
    return fmt::format(
        "a victim level holds memory.{}'s evicted lines as they are: its line_bytes and "
        "sector_bytes must be that level's",
        above.name);
  return {};
}

}  // namespace

std::string hierarchy_problem(const std::vector<MemoryLevelConfig>& levels) {
  if (levels.empty() || levels.size() > kMaxCacheLevels)
    return fmt::format("[memory] a hierarchy has 1 to {} cache levels, not {}", kMaxCacheLevels,
                       levels.size());
  for (size_t i = 0; i < levels.size(); ++i) {
    const std::string& name = levels[i].name;
    if (!valid_name(name))
      return fmt::format(
          "[memory] level name '{}': lower-case letters, digits and _, starting with a letter, "
          "at most 32 (and not 'levels')",
          name);
    for (size_t j = 0; j < i; ++j)
      if (levels[j].name == name) return fmt::format("[memory] two levels are named '{}'", name);
    std::string p = level_problem(levels, i);
    if (!p.empty()) return fmt::format("[memory.{}] {}", name, p);
  }
  return {};
}

CachePlace cache_place(const std::vector<MemoryLevelConfig>& levels, uint32_t index) {
  CachePlace place;
  place.level = index;
  place.above_dram = index + 1 == levels.size();
  place.fill_on_miss = levels[index].fill == LevelFill::Miss;
  place.victims_below = !place.above_dram && levels[index + 1].fill == LevelFill::Victim;
  return place;
}

}  // namespace rtsim
