// Runs RT cores to completion the way their SystemC module does (wake at the next event,
// handle it, ask for rays when waiting), but without a kernel, for tests of the plain units.
#pragma once

#include <algorithm>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/sched/rt_core.h"

namespace rtsim::test {

// Returns the cycle the last core finished; throws if no core can make progress.
// after_cycle (optional) runs after every handled cycle: a deferred memory answers there.
inline Cycle drive(const std::vector<RtCore*>& cores,
                   const std::function<void()>& after_cycle = {}) {
  Cycle now = 0;
  for (RtCore* core : cores) core->poll(0);
  for (;;) {
    bool running = false;
    Cycle next = ~Cycle(0);
    for (RtCore* core : cores) {
      running |= !core->finished();
      if (core->has_event()) next = std::min(next, core->next_event());
    }
    if (!running) return now;
    if (next == ~Cycle(0)) {
      uint64_t progress = 0;
      for (RtCore* core : cores)
        if (core->waiting()) progress += core->poll(now);
      bool all_finished = true;
      for (RtCore* core : cores) all_finished &= core->finished();
      if (all_finished) return now;
      if (progress == 0) {
        std::string dump;
        for (RtCore* core : cores) dump += core->dump();
        throw std::runtime_error("no core can make progress:\n" + dump);
      }
      continue;
    }
    now = next;
    for (RtCore* core : cores) {
      if (core->waiting()) core->poll(now);
      core->advance(now + 1);
    }
    if (after_cycle) after_cycle();
  }
}

}  // namespace rtsim::test
