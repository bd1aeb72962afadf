// Cache hierarchies of any depth ([[memory.level]], model/mem/hierarchy.h): a unit's own levels
// (model/sc/tlm_memory.h) in front of group and shared levels (model/sc/shared_levels_module.h)
// and a simple DRAM. Each level's hit latency holds to the cycle for 1, 3 and 5 levels, and a
// victim level takes the lines the level above evicts, so that a re-read hits there.
#include <gtest/gtest.h>

#include <vector>

#include "model/sc/shared_levels_module.h"
#include "model/sc/tlm_memory.h"

namespace rtsim {
namespace {

constexpr uint32_t kDramLatency = 100;

MemoryLevelConfig level(const std::string& name, LevelScope scope, uint32_t hit_latency,
                        uint32_t link_latency, uint64_t size = 64 * 1024, uint32_t ways = 4) {
  MemoryLevelConfig l;
  l.name = name;
  l.scope = scope;
  l.cache = CacheConfig{size, 64, ways, "lru", hit_latency, 8};
  l.link.latency = link_latency;
  return l;
}

// A unit that reads its first level at given cycles, in order, and notes each read's data
// cycle and what it cost at each level.
struct Reader : sc_core::sc_module, ReadClient {
  SC_HAS_PROCESS(Reader);
  Reader(sc_core::sc_module_name name, const std::vector<MemoryLevelConfig>& levels)
      : sc_module(name), memory("mem", levels) {
    SC_THREAD(run);
  }
  void run() {
    ready.assign(script.size(), kPending);
    charges.assign(script.size(), {});
    for (size_t i = 0; i < script.size(); ++i) {
      auto [addr, at] = script[i];
      wait(clock.time(at) - sc_core::sc_time_stamp());
      Cycle r = memory.cache().read(addr, 64, at, this, i, charges[i]);
      if (r != kPending) ready[i] = r;
    }
  }
  void read_done(uint64_t token, Cycle at, const ReadCharge& charge) override {
    ready[token] = at;
    charges[token] += charge;
  }
  Clock clock;
  UnitMemory memory;
  std::vector<std::pair<uint64_t, Cycle>> script;
  std::vector<Cycle> ready;
  std::vector<ReadCharge> charges;
};

// What the shared levels may rely on: the unit's last own level sends after its tag check.
uint32_t last_own_hit_latency(const std::vector<MemoryLevelConfig>& levels) {
  return levels[own_levels(levels) - 1].cache.hit_latency;
}

// The machine: one reader (unit 0) on the levels, a simple DRAM below.
struct Machine {
  explicit Machine(const std::vector<MemoryLevelConfig>& levels)
      : reader("unit", levels),
        shared("shared", levels, 1, reader.clock, last_own_hit_latency(levels)),
        dram("dram", DramConfig{64.0, kDramLatency, 64}, reader.clock) {
    reader.memory.connect(shared, 0);
    shared.out.bind(dram.in);
  }
  // Cache::warm on level i's cache that unit 0 reaches: the line is there and nowhere else.
  void place(const std::vector<MemoryLevelConfig>& levels, uint32_t i, uint64_t addr) {
    if (!queued_level(levels[i])) {
      reader.memory.level(i).warm(addr, 64, 0);
      return;
    }
    const auto& inst = shared.instances()[shared.instances_of(i).first];
    inst.slices[shared.slice_of(inst, addr)]->warm(addr, 64, 0);
  }
  Reader reader;
  SharedLevelsModule shared;
  DramModule dram;
};

// Data cycles of a read that hits at level k: every level above checks its tags first, and a
// request crosses each link between shared levels both ways.
Cycle hit_cycles(const std::vector<MemoryLevelConfig>& levels, uint32_t k) {
  Cycle cycles = 0;
  for (uint32_t i = 0; i <= k; ++i) cycles += levels[i].cache.hit_latency;
  for (uint32_t i = 0; i < k; ++i) cycles += 2 * levels[i].link.latency;
  return cycles;
}

// Places a line in each level alone, reads each (and one that is nowhere) 1,000 cycles apart.
void expect_hit_latencies(const std::vector<MemoryLevelConfig>& levels) {
  Machine m(levels);
  uint32_t n = uint32_t(levels.size());
  for (uint32_t k = 0; k < n; ++k) {
    m.place(levels, k, 0x10000 * (k + 1));
    m.reader.script.push_back({0x10000 * (k + 1), 1000 * (k + 1)});
  }
  m.reader.script.push_back({0x900000, 1000 * (n + 1)});
  sc_core::sc_start();
  for (uint32_t k = 0; k < n; ++k) {
    EXPECT_EQ(m.reader.ready[k], 1000 * (k + 1) + hit_cycles(levels, k)) << levels[k].name;
    EXPECT_EQ(m.reader.charges[k].hits[k], 1u) << levels[k].name << " counts the hit";
    EXPECT_EQ(m.reader.charges[k].accesses[k], 1u) << levels[k].name;
    if (k > 0) EXPECT_EQ(m.reader.charges[k].hits[k - 1], 0u) << "a miss above";
  }
  // Nowhere: every level's tag check and link, then DRAM (a 64-byte burst is one bus cycle).
  Cycle dram = hit_cycles(levels, n - 1) + 2 * levels[n - 1].link.latency + kDramLatency + 1;
  EXPECT_EQ(m.reader.ready[n], 1000 * (n + 1) + dram);
  EXPECT_EQ(m.reader.charges[n].dram_bytes, 64u) << "the last level counts DRAM bytes";
}

TEST(MemoryLevels, OneLevelHitsAndMissesToTheCycle) {
  expect_hit_latencies({level("l1", LevelScope::Unit, 7, 0)});
}

TEST(MemoryLevels, ThreeLevelsHitToTheCycle) {
  expect_hit_latencies({level("l1", LevelScope::Unit, 7, 3), level("l2", LevelScope::Shared, 30, 5),
                        level("l3", LevelScope::Shared, 60, 0)});
}

TEST(MemoryLevels, FiveLevelsHitToTheCycle) {
  MemoryLevelConfig group = level("l1", LevelScope::Group, 25, 4);
  group.group = 4;
  expect_hit_latencies({level("l0", LevelScope::Unit, 4, 0), level("lb", LevelScope::Unit, 9, 2),
                        group, level("l2", LevelScope::Shared, 70, 6),
                        level("l3", LevelScope::Shared, 120, 0)});
}

// l1 and l2 hold one line of a set; A and B share both sets. Reading B evicts A from the L2 into
// the victim level, where a re-read of A then hits.
TEST(MemoryLevels, AVictimLevelTakesTheL2sEvictionsAndARereadHitsThere) {
  std::vector<MemoryLevelConfig> levels = {level("l1", LevelScope::Unit, 5, 2, 64, 1),
                                           level("l2", LevelScope::Shared, 20, 3, 128, 1),
                                           level("ic", LevelScope::Shared, 50, 0)};
  levels[2].fill = LevelFill::Victim;
  ASSERT_EQ(hierarchy_problem(levels), "");
  Machine m(levels);
  m.reader.script = {{0x0, 10}, {0x80, 1000}, {0x0, 2000}};
  sc_core::sc_start();
  const CacheStats& l2 = m.shared.instances()[0].stats();
  const CacheStats& ic = m.shared.instances()[1].stats();
  EXPECT_EQ(l2.victims, 2u) << "A, then B: clean lines sent on their eviction";
  EXPECT_EQ(ic.victim_fills, 2u);
  EXPECT_EQ(ic.misses, 2u) << "A and B went below the victim level without a line there";
  EXPECT_EQ(ic.hits, 1u) << "the re-read of A";
  EXPECT_EQ(m.reader.ready[2], 2000 + hit_cycles(levels, 2));
  EXPECT_EQ(m.reader.charges[2].hits[2], 1u);
  EXPECT_EQ(m.reader.charges[2].dram_bytes, 0u);
  EXPECT_EQ(m.dram.dram().stats().requests, 2u) << "A once, B once";
}

// Without the victim fill the same reads go to DRAM a third time.
TEST(MemoryLevels, AMissFilledLastLevelDoesNotTakeEvictions) {
  std::vector<MemoryLevelConfig> levels = {level("l1", LevelScope::Unit, 5, 2, 64, 1),
                                           level("l2", LevelScope::Shared, 20, 3, 128, 1),
                                           level("l3", LevelScope::Shared, 50, 0, 128, 1)};
  Machine m(levels);
  m.reader.script = {{0x0, 10}, {0x80, 1000}, {0x0, 2000}};
  sc_core::sc_start();
  EXPECT_EQ(m.shared.instances()[0].stats().victims, 0u);
  EXPECT_EQ(m.dram.dram().stats().requests, 3u);
}

TEST(MemoryLevels, HierarchyProblemsNameTheLevel) {
  std::vector<MemoryLevelConfig> shared_first = {level("l2", LevelScope::Shared, 20, 0)};
  EXPECT_NE(hierarchy_problem(shared_first).find("[memory.l2] the first level"), std::string::npos);
  std::vector<MemoryLevelConfig> unit_below = {level("l1", LevelScope::Unit, 5, 1),
                                               level("l2", LevelScope::Shared, 20, 0),
                                               level("l3", LevelScope::Unit, 5, 0)};
  EXPECT_NE(hierarchy_problem(unit_below).find("[memory.l3] scope unit cannot follow shared"),
            std::string::npos);
  std::vector<MemoryLevelConfig> victim = {level("l1", LevelScope::Unit, 5, 1),
                                           level("ic", LevelScope::Shared, 20, 0)};
  victim[1].fill = LevelFill::Victim;
  victim[1].cache.line_bytes = 128;
  EXPECT_NE(hierarchy_problem(victim).find("[memory.ic] a victim level"), std::string::npos);
  std::vector<MemoryLevelConfig> twice = {level("l1", LevelScope::Unit, 5, 1),
                                          level("l1", LevelScope::Shared, 20, 0)};
  EXPECT_NE(hierarchy_problem(twice).find("two levels are named 'l1'"), std::string::npos);
}

}  // namespace
}  // namespace rtsim
