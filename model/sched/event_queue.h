// The pending events of one simulated unit: (cycle, item) pairs served earliest cycle first,
// and in insertion order within a cycle, so a run is deterministic. A unit keeps one queue
// for all its rays instead of a SystemC thread per ray, and wakes only at the cycles in it.
#pragma once

#include <cstdint>
#include <queue>
#include <vector>

#include "model/mem/memory_level.h"

namespace rtsim {

class EventQueue {
public:
  struct Event {
    Cycle cycle = 0;
    uint64_t order = 0;  // insertion number: ties at one cycle are served first in, first out
    uint32_t item = 0;   // what the owner schedules: a ray slot or a warp
  };

  void push(Cycle cycle, uint32_t item) { heap_.push({cycle, next_order_++, item}); }
  bool empty() const { return heap_.empty(); }
  size_t size() const { return heap_.size(); }
  const Event& top() const { return heap_.top(); }
  Event pop() {
    Event e = heap_.top();
    heap_.pop();
    return e;
  }

private:
  struct Later {
    bool operator()(const Event& a, const Event& b) const {
      return a.cycle != b.cycle ? a.cycle > b.cycle : a.order > b.order;
    }
  };
  std::priority_queue<Event, std::vector<Event>, Later> heap_;
  uint64_t next_order_ = 0;
};

}  // namespace rtsim
