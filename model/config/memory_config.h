// The [memory] part of a hardware config: the cache levels (model/mem/hierarchy.h), read from
// [[memory.level]] tables (or the shorthand [rt.l1], [xbar] and [l2] of a two-level machine),
// each level's keys under memory.NAME.
#pragma once

#include <toml++/toml.h>

#include <vector>

#include "model/config/config_reader.h"
#include "model/mem/hierarchy.h"

namespace rtsim {

// Before the --set overrides: turns the [[memory.level]] list into memory.levels (the names in
// order) and a memory.NAME table per level, so that an override can name a level's key
// (memory.l2.size_bytes). Throws InputError naming the file and line of a level without a
// name, a name given twice, or a list beside memory.levels.
void name_memory_levels(toml::table& root, ConfigReadContext& ctx);

// After the overrides: the shorthand sections [rt.l1], [xbar] and [l2] become memory.l1 (its
// link to the next level from [xbar]) and memory.l2, and messages name keys as written. Giving
// both the shorthand and [memory] is InputError naming where the shorthand came from.
void expand_cache_shorthand(toml::table& root, ConfigReadContext& ctx);

// Reads memory.levels and each level's keys; `levels` holds the defaults (a level keeps the
// defaults of the one of its name) and receives what was read.
void read_memory_levels(ConfigReader r, std::vector<MemoryLevelConfig>& levels);

}  // namespace rtsim
