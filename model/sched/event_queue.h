// The pending events of one simulated unit: (cycle, item) pairs served earliest cycle first,
// and in insertion order within a cycle, so a run is deterministic. A unit keeps one queue
// for all its rays instead of a SystemC thread per ray, and wakes only at the cycles in it.
// A timing wheel: events within kWheel cycles of the earliest pending cycle sit in per-cycle
// FIFO arrays (constant time per event, and contiguous in memory: a linked list's nodes cost a
// host cache miss per event); later ones wait in a heap and move onto the wheel as it turns. Events
// must not be scheduled before the last cycle popped.
#pragma once

#include <cstddef>
#include <cstdint>
#include <queue>
#include <vector>

#include "model/mem/memory_level.h"

namespace rtsim {

class EventQueue {
 public:
  struct Event {
    Cycle cycle = 0;
    uint32_t item = 0;  // what the owner schedules: a ray slot or a warp
  };
  static constexpr uint32_t kWheel = 512;

  EventQueue();
  void push(Cycle cycle, uint32_t item) {
    if (cycle < cursor_) throw_past();
    size_++;
    if (cycle < cursor_ + kWheel)
      append(cycle, item);
    else
      push_far(cycle, item);
  }
  bool empty() const { return size_ == 0; }
  size_t size() const { return size_; }
  // The earliest pending cycle (the queue must not be empty). Only pop() turns the wheel, so
  // events may still be pushed for any cycle from the last one popped on.
  Cycle next_cycle() const;
  Event pop();
  // Pops the earliest event if it is before cycle `until` (then true); else changes nothing.
  bool pop_before(Cycle until, Event& event) {
    if (size_ == 0) return false;
    // Events left at the cursor's cycle (several in one cycle) need no scan for the next one.
    if (on_wheel_ == 0 || !occupied(cursor_)) return turn_before(until, event);
    if (cursor_ >= until) return false;
    event = take_at_cursor();
    return true;
  }

 private:
  struct Slot {
    std::vector<uint32_t> items;  // the items of one cycle in order; items[next] is the first
    uint32_t next = 0;
  };
  struct Far {
    Cycle cycle;
    uint64_t order;
    uint32_t item;
    bool operator>(const Far& o) const {
      return cycle != o.cycle ? cycle > o.cycle : order > o.order;
    }
  };
  void append(Cycle cycle, uint32_t item) {
    uint32_t slot = uint32_t(cycle % kWheel);
    occupied_[slot / 64] |= 1ull << (slot % 64);
    slots_[slot].items.push_back(item);
    on_wheel_++;
  }
  [[noreturn]] static void throw_past();
  void push_far(Cycle cycle, uint32_t item);
  // pop_before when the cursor's cycle has no event left: turns the wheel to the next one.
  bool turn_before(Cycle until, Event& event);
  void settle();            // turns the wheel to the earliest pending cycle
  void pull_far();          // moves far events within kWheel of the cursor onto the wheel
  Event take_at_cursor() {  // the first event at the cursor's cycle, which has one
    uint32_t slot = uint32_t(cursor_ % kWheel);
    Slot& s = slots_[slot];
    Event e{cursor_, s.items[s.next++]};
    if (s.next == s.items.size()) {
      s.items.clear();  // keeps its capacity for the cycles to come
      s.next = 0;
      occupied_[slot / 64] &= ~(1ull << (slot % 64));
    }
    size_--;
    on_wheel_--;
    return e;
  }
  uint32_t gap(Cycle from) const;
  bool occupied(Cycle cycle) const {
    uint32_t slot = uint32_t(cycle % kWheel);
    return (occupied_[slot / 64] >> (slot % 64)) & 1;
  }

  Cycle cursor_ = 0;                     // no pending event is earlier
  std::vector<Slot> slots_;              // per wheel slot
  uint64_t occupied_[kWheel / 64] = {};  // bit per wheel slot with events: skips idle cycles
  size_t size_ = 0, on_wheel_ = 0;
  uint64_t far_order_ = 0;
  std::priority_queue<Far, std::vector<Far>, std::greater<Far>> far_;
};

}  // namespace rtsim
