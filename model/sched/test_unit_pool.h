// A pool of identical pipelined test units of an RT unit: the ray-box units (one pass tests
// up to issue_width child boxes of a node) or the ray-triangle units (issue_width triangles).
// Timing: each of `count` units accepts one issue per cycle of up to issue_width tests, fully
// pipelined; the results of an issue at cycle c are ready at c + latency. A request of n tests
// needs ceil(n / issue_width) issues, taken from the earliest cycles at or after its arrival
// that still have a free unit (several units in one cycle, or consecutive cycles); it is ready
// `latency` cycles after its last issue. A request that finds every unit taken waits
// (back-pressure, counted as stall cycles). Reservations live in a small cycle calendar, so
// requests may come in any order of their arrival cycles; reservations more than
// kCalendarCycles apart share an entry, and then the earlier cycle counts as fully booked
// (conservative; counted as calendar_conflicts, zero in practice). Booked cycles keep skip
// hints with path compression (as in union-find), so a busy pool finds its next free cycle
// in near-constant time.
// Shared issue slots (reserve_as): one pool's units may take the issues of another kind of
// test, each issue either kind's width and latency, as AMD's ray accelerator does 4 box tests
// or 1 triangle test a clock (RDNA2/3; RDNA4: 8 or 2). Tests a clock = count x issue_width.
// Follows the fixed-function box/triangle units of Aila & Karras (HPG 2010) and RT cores.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "model/mem/memory_level.h"

namespace rtsim {

struct TestUnitConfig {
  uint32_t count = 1;        // units: identical pipelines in the pool
  uint32_t issue_width = 1;  // tests: boxes or triangles one issue handles
  uint32_t latency = 8;      // cycles: from an issue to its results
};

// Why the config is impossible (empty if fine).
std::string test_unit_config_problem(const TestUnitConfig& config);

struct TestUnitStats {
  uint64_t requests = 0;            // steps served (a node's boxes, or a leaf's triangles)
  uint64_t tests = 0;               // boxes or triangles tested
  uint64_t issues = 0;              // issue slots used (the busy unit-cycles)
  uint64_t stall_cycles = 0;        // sum over requests of first issue - arrival
  uint64_t calendar_conflicts = 0;  // cycles taken as booked because a later one held the entry
};

class TestUnitPool {
 public:
  static constexpr uint32_t kCalendarCycles = 1u << 10;

  explicit TestUnitPool(const TestUnitConfig& config);  // throws std::invalid_argument

  // Reserves the issues for `tests` tests arriving at cycle `arrival`; returns the cycle their
  // results are ready. tests = 0 is treated as 1 (a step always passes through the unit).
  Cycle reserve(Cycle arrival, uint32_t tests) { return reserve_as(*this, arrival, tests); }
  // Reserves tests of `kind` (its issue width and latency, counted in its stats) in this pool's
  // issue slots: the units serve either kind, one issue each per cycle. Conflicts of the
  // calendar count in this pool's stats.
  Cycle reserve_as(TestUnitPool& kind, Cycle arrival, uint32_t tests);
  const TestUnitStats& stats() const { return stats_; }
  const TestUnitConfig& config() const { return config_; }

 private:
  struct Slot {
    uint32_t epoch = 0;  // cycle / kCalendarCycles + 1 of the cycle this entry counts for
    uint16_t used = 0;   // issues taken in that cycle
    uint16_t skip = 0;   // when booked: cycles to jump ahead to look for a free one (a hint)
  };
  // The entry of `cycle` (reset if it held an earlier cycle), or nullptr if it holds a later
  // one (count as booked); slot_at also counts that as a calendar conflict.
  Slot* entry(Cycle cycle);
  Slot* slot_at(Cycle cycle);
  // Moves `cycle` to the first cycle at or after it with a free issue and returns its entry;
  // shortens the skips it followed.
  Slot* find_free(Cycle& cycle);

  TestUnitConfig config_;
  std::vector<Slot> calendar_;
  TestUnitStats stats_;
};

}  // namespace rtsim
