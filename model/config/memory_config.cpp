#include "model/config/memory_config.h"

#include <algorithm>

#include <fmt/format.h>

#include "model/config/hw_config.h"
#include "traces/error.h"

namespace rtsim {
namespace {

using Zero = ConfigReader::Zero;

std::string line_of(const toml::node& node) {
  return node.source().begin ? fmt::format("line {}", node.source().begin.line) : "";
}

void read_cache(ConfigReader r, CacheConfig& c, const char* which) {
  c.size_bytes =
      r.size("size_bytes", c.size_bytes, fmt::format("data capacity of {}", which).c_str(),
             kMinCacheBytes, kMaxCacheBytes);
  c.line_bytes = uint32_t(r.size("line_bytes", c.line_bytes, "line size, a power of two", 4, 4096));
  c.sector_bytes = uint32_t(r.size(
      "sector_bytes", c.sector_bytes,
      "fetch unit of a miss, a power of two dividing the line; 0 = the whole line", 0, 4096));
  c.ways = uint32_t(r.integer("ways", c.ways, "lines", "associativity: lines per set", 1, 1024));
  c.replacement =
      r.text("replacement", c.replacement, "replacement policy", replacement_policy_names());
  c.hit_latency =
      uint32_t(r.integer("hit_latency", c.hit_latency, "cycles",
                         "request to data on a hit; also the tag check of a miss", 0, 100000));
  c.mshrs =
      uint32_t(r.integer("mshrs", c.mshrs, "count", "block misses in flight at once", 1, 65536));
  c.merge_limit = uint32_t(r.integer("merge_limit", c.merge_limit, "requests",
                                     "requests one MSHR takes besides its own (more replay after "
                                     "the data); 0 = no limit",
                                     0, 65535));
  c.banks = uint32_t(
      r.integer("banks", c.banks, "banks", "lines interleaved over them, a power of two", 1, 1024));
  c.bank_ports = uint32_t(r.integer("bank_ports", c.bank_ports, "lookups/cycle",
                                    "lookups one bank starts per cycle; 0 = no limit", 0, 1024));
  c.bytes_per_cycle = r.rate("bytes_per_cycle", c.bytes_per_cycle, "bytes/cycle",
                             "data port bandwidth (reads and writes)", kMinPortBytesPerCycle,
                             kMaxBytesPerCycle, Zero::NoLimit);
}

void read_level(ConfigReader r, MemoryLevelConfig& l) {
  std::string scope = r.text("scope", scope_name(l),
                             "who has an instance: unit (one per RT unit; the first level), "
                             "group:N (one per N units, in unit order) or shared (one)");
  if (!parse_scope(scope, l))
    r.fail("scope", fmt::format("'{}' is not unit, group:N (N from 1 to 1024) or shared", scope));
  std::string fill = r.text("fill", l.fill == LevelFill::Victim ? "victim" : "miss",
                            "miss: a read miss fetches its block; victim: filled by the lines "
                            "the level above evicts, a read miss goes below without a line here",
                            {"miss", "victim"});
  l.fill = fill == "victim" ? LevelFill::Victim : LevelFill::Miss;
  read_cache(r, l.cache, "one instance (all its slices)");
  l.slices = uint32_t(r.integer("slices", l.slices, "slices",
                                "group and shared levels: address-hashed slices of size_bytes / "
                                "slices each; mshrs, banks and bandwidth are per slice",
                                1, 1024));
  l.link.latency = uint32_t(r.integer("link_latency", l.link.latency, "cycles",
                                      "the crossbar from this level's instances to the next "
                                      "level's slices, each way",
                                      0, 100000));
  l.link.bytes_per_cycle =
      r.rate("link_bytes_per_cycle", l.link.bytes_per_cycle, "bytes/cycle",
             "each port of that crossbar (one per instance above, one per slice), each direction",
             kMinPortBytesPerCycle, kMaxBytesPerCycle, Zero::NoLimit);
}

// Where the shorthand came from, for a message: its --set, or the file and line of its section.
struct Place {
  std::string where, line;
};

Place shorthand_place(const toml::node& section, const std::string& key,
                      const ConfigReadContext& ctx) {
  for (const std::string& a : ctx.set_assignments)
    if (a.compare(0, key.size() + 1, key + ".") == 0) return {ctx.set_option + " " + a, ""};
  return {ctx.file, line_of(section)};
}

}  // namespace

void name_memory_levels(toml::table& root, ConfigReadContext& ctx) {
  toml::table* memory = root["memory"].as_table();
  if (!memory || !memory->contains("level")) return;
  toml::node& list = *memory->get("level");
  toml::array* levels = list.as_array();
  if (!levels || !levels->is_array_of_tables())
    throw_input_error(ctx.file, line_of(list),
                      "memory.level must be a list of [[memory.level]] tables");
  if (memory->contains("levels"))
    throw_input_error(ctx.file, line_of(*memory->get("levels")),
                      "give the levels as [[memory.level]] tables or as memory.levels, not both");
  toml::array names;
  toml::table named;
  for (toml::node& node : *levels) {
    // Moved, not copied: a copied toml++ node loses its source lines, which errors name.
    toml::table level = std::move(*node.as_table());
    auto name = level["name"].value_exact<std::string>();
    if (!name)
      throw_input_error(ctx.file, line_of(level),
                        "a [[memory.level]] needs name = \"...\" (its stats are mem.NAME.*)");
    if (named.contains(*name) || memory->contains(*name))
      throw_input_error(ctx.file, line_of(level),
                        fmt::format("two [[memory.level]] tables are named '{}'", *name));
    level.erase("name");
    names.push_back(*name);
    named.insert(*name, std::move(level));
  }
  memory->erase("level");
  memory->insert("levels", std::move(names));
  for (auto&& [name, level] : named) memory->insert(name, std::move(level));
}

// A memory.NAME section of a level memory.levels does not list (a misspelt name, say).
void check_level_names(const toml::table& root, const ConfigReadContext& ctx) {
  const toml::table* memory = root["memory"].as_table();
  const toml::array* names = memory ? (*memory)["levels"].as_array() : nullptr;
  if (!memory || !names) return;
  std::string listed;
  for (const toml::node& n : *names)
    listed += (listed.empty() ? "" : ", ") + n.value_or(std::string());
  for (auto&& [key, node] : *memory) {
    std::string name(key.str());
    if (!node.is_table() || std::any_of(names->begin(), names->end(), [&](const toml::node& n) {
          return n.value_or(std::string()) == name;
        }))
      continue;
    std::string what = fmt::format("memory.{}: no level of that name (levels: {})", name, listed);
    std::string set = ctx.set_place("memory." + name);
    for (const std::string& a : ctx.set_assignments)
      if (a.compare(0, 8 + name.size(), "memory." + name + ".") == 0)
        set = ctx.set_option + " " + a;
    if (!set.empty()) throw_input_error(set, "", what);
    throw_input_error(ctx.file, line_of(node), what);
  }
}

void expand_cache_shorthand(toml::table& root, ConfigReadContext& ctx) {
  check_level_names(root, ctx);
  toml::table* rt = root["rt"].as_table();
  toml::node* l1 = rt ? rt->get("l1") : nullptr;
  toml::node* l2 = root.get("l2");
  toml::node* xbar = root.get("xbar");
  std::pair<toml::node*, const char*> given[] = {{l1, "rt.l1"}, {xbar, "xbar"}, {l2, "l2"}};
  auto first = std::find_if(std::begin(given), std::end(given),
                            [](const auto& g) { return g.first && g.first->is_table(); });
  if (first == std::end(given)) return;
  if (const toml::node* listed = root.get("memory")) {
    Place p = shorthand_place(*first->first, first->second, ctx);
    // A [memory] that only overrides made (it has no line) is theirs to blame.
    if (!listed->source().begin && p.where == ctx.file) p = shorthand_place(*listed, "memory", ctx);
    throw_input_error(p.where, p.line,
                      fmt::format("[{}] is the shorthand of a two-level hierarchy, and [memory] "
                                  "lists the levels: give one of them (memory.NAME.KEY sets a "
                                  "listed level's key)",
                                  first->second));
  }
  // Moved, not copied: a copied toml++ node loses its source lines, which errors name.
  toml::table memory, own, shared;
  if (l1 && l1->is_table()) {
    own = std::move(*l1->as_table());
    rt->erase("l1");
  }
  if (l2 && l2->is_table()) {
    shared = std::move(*l2->as_table());
    root.erase("l2");
  }
  if (xbar && xbar->is_table()) {
    toml::table& links = *xbar->as_table();
    for (const char* key : {"latency", "bytes_per_cycle"})
      if (toml::node* value = links.get(key)) {
        own.insert(std::string("link_") + key, std::move(*value));
        links.erase(key);
      }
    if (links.empty()) root.erase("xbar");
    ctx.sections.push_back("xbar");  // its other keys are unknown ones
  }
  memory.insert("levels", toml::array{"l1", "l2"});
  memory.insert("l1", std::move(own));
  memory.insert("l2", std::move(shared));
  root.insert("memory", std::move(memory));
  ctx.aliases = {{"memory.l1.link_latency", "xbar.latency"},
                 {"memory.l1.link_bytes_per_cycle", "xbar.bytes_per_cycle"},
                 {"[memory.l1]", "[rt.l1]"},
                 {"[memory.l2]", "[l2]"},
                 {"memory.l1", "rt.l1"},
                 {"memory.l2", "l2"}};
}

void read_memory_levels(ConfigReader r, std::vector<MemoryLevelConfig>& levels) {
  std::vector<std::string> defaults;
  for (const MemoryLevelConfig& l : levels) defaults.push_back(l.name);
  std::vector<std::string> names =
      r.strings("levels", defaults,
                "the cache levels' names from the RT unit outwards, each level's keys under "
                "memory.NAME (a [[memory.level]] list with name = \"NAME\" sets both; [rt.l1], "
                "[xbar] and [l2] are the shorthand of l1 and l2); stats are mem.NAME.*");
  if (names.empty() || names.size() > kMaxCacheLevels)
    r.fail("levels", fmt::format("a hierarchy has 1 to {} levels", kMaxCacheLevels));
  std::vector<MemoryLevelConfig> read;
  for (const std::string& name : names) {
    auto known = std::find_if(levels.begin(), levels.end(),
                              [&](const MemoryLevelConfig& l) { return l.name == name; });
    MemoryLevelConfig level;
    if (known != levels.end()) level = *known;
    level.name = name;
    if (name == "levels" || name.find('.') != std::string::npos)
      r.fail("levels", fmt::format("'{}' cannot name a level", name));
    read_level(r.section(name), level);
    read.push_back(level);
  }
  levels = std::move(read);
}

}  // namespace rtsim
