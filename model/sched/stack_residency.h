// Where a traversal stack's entries live, on chip or spilled to memory: the rule of the RT
// unit's stack (model/sched/hardware_stack.h) in counts only, shared by every level that models
// spills (the cycle model, the cache level, the warmed sampling).
#pragma once

#include <algorithm>
#include <cstdint>

namespace rtsim {

// `resident` entries on chip (the stack's top) and `spilled` in memory below them; it counts
// entries and moves none.
struct StackResidency {
  uint32_t resident = 1, spilled = 0;  // a ray starts with its root entry on chip

  // Before a step that pops `pops` entries: the spilled ones it needs come back on chip.
  // Returns how many: entries spilled .. spilled + need - 1 after the call.
  uint32_t refill(uint32_t pops) {
    if (pops <= resident || spilled == 0) return 0;
    uint32_t need = std::min(spilled, pops - resident);
    spilled -= need;
    resident += need;
    return need;
  }
  // After a step: `kept` entries of the stack before it survive below `total` entries now; what
  // no longer fits in `depth` on-chip entries spills. Returns how many: entries spilled - out ..
  // spilled - 1 after the call.
  uint32_t settle(uint32_t kept, uint32_t total, uint32_t depth) {
    spilled = std::min({spilled, kept, total});  // spilled entries are the oldest: they survive
    resident = total - spilled;
    if (resident <= depth) return 0;
    uint32_t out = resident - depth;
    spilled += out;
    resident = depth;
    return out;
  }
};

}  // namespace rtsim
