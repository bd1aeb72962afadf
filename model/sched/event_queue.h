// The pending events of one simulated unit: (cycle, item) pairs served earliest cycle first,
// and in insertion order within a cycle, so a run is deterministic. A unit keeps one queue
// for all its rays instead of a SystemC thread per ray, and wakes only at the cycles in it.
// The item is what the owner schedules: a ray slot or warp (EventQueue), or a whole request
// record (the shared L2's jobs, model/sc/shared_levels_module.h), kept in the queue itself.
// A timing wheel: events within kWheel cycles of the earliest pending cycle sit in per-cycle
// FIFO arrays (constant time per event, and contiguous in memory: a linked list's nodes cost a
// host cache miss per event); later ones wait in a heap and move onto the wheel as it turns. Events
// must not be scheduled before the last cycle popped. A cycle's first few ray slots lie in its
// wheel slot itself, one host cache line: with thousands of rays in flight the wheel is cold when
// it comes round, and a slot with its items elsewhere cost a second miss.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <queue>
#include <vector>

#include "model/mem/memory_level.h"

namespace rtsim {

[[noreturn]] void throw_event_in_past();

template <class Item>
class Calendar {
 public:
  struct Event {
    Cycle cycle = 0;
    Item item{};
  };
  static constexpr uint32_t kWheel = 512;

  Calendar() : slots_(kWheel) {}
  void push(Cycle cycle, const Item& item) {
    if (cycle < cursor_) throw_event_in_past();
    size_++;
    if (cycle < cursor_ + kWheel)
      append(cycle, item);
    else
      far_.push({cycle, far_order_++, item});
  }
  bool empty() const { return size_ == 0; }
  size_t size() const { return size_; }
  // The earliest pending cycle (the queue must not be empty). Only pop() turns the wheel, so
  // events may still be pushed for any cycle from the last one popped on.
  Cycle next_cycle() const {
    if (on_wheel_ == 0) return far_.top().cycle;
    return cursor_ + gap(cursor_);
  }
  Event pop() {
    settle();
    return take_at_cursor();
  }
  // For hints to the host about what comes next: the item the next pop returns if nothing is
  // pushed first (false: none on the wheel).
  bool peek(Item& item) const {
    if (on_wheel_ == 0) return false;
    const Slot& s = slots_[(cursor_ + gap(cursor_)) % kWheel];
    item = s[s.next];
    return true;
  }
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
  // The items of one cycle in order, the first kInline of them here, in the slot's host cache
  // line (small items: a unit's ray slots; a request record is too big for it); item `next` is
  // the first not yet taken.
  static constexpr uint32_t kInline = 32 / sizeof(Item);
  // A host line of its own when it holds items (a 64-byte slot for the L2's records measured
  // more host misses than their 40-byte one).
  struct alignas(kInline > 0 ? 64 : alignof(std::vector<Item>)) Slot {
    uint32_t next = 0, count = 0;
    std::array<Item, kInline> first{};
    std::vector<Item> more;  // items kInline on (keeps its capacity)
    void push(const Item& item) {
      if (count < kInline)
        first[count] = item;
      else
        more.push_back(item);
      count++;
    }
    const Item& operator[](uint32_t i) const { return i < kInline ? first[i] : more[i - kInline]; }
  };
  struct Far {
    Cycle cycle;
    uint64_t order;
    Item item;
    bool operator>(const Far& o) const {
      return cycle != o.cycle ? cycle > o.cycle : order > o.order;
    }
  };
  void append(Cycle cycle, const Item& item) {
    uint32_t slot = uint32_t(cycle % kWheel);
    occupied_[slot / 64] |= 1ull << (slot % 64);
    slots_[slot].push(item);
    on_wheel_++;
  }
  // pop_before when the cursor's cycle has no event left: turns the wheel to the next one.
  [[gnu::noinline]] bool turn_before(Cycle until, Event& event) {
    Cycle next = next_cycle();
    if (next >= until) return false;
    cursor_ = next;  // turn the wheel to it, as settle() would, without a second scan
    pull_far();
    event = take_at_cursor();
    return true;
  }
  // Turns the wheel to the earliest pending cycle.
  void settle() {
    while (!occupied(cursor_)) {
      if (on_wheel_ == 0) {
        cursor_ = far_.top().cycle;  // nothing near: jump to the far events
      } else {
        // Skip idle cycles, but stop where far events must join the wheel.
        Cycle next = cursor_ + std::min<uint32_t>(gap(cursor_), kWheel);
        if (!far_.empty()) next = std::min(next, far_.top().cycle - kWheel + 1);
        cursor_ = std::max(next, cursor_ + 1);
      }
      pull_far();
    }
  }
  // Far events that came within reach of the cursor join the wheel, in their order.
  void pull_far() {
    while (!far_.empty() && far_.top().cycle < cursor_ + kWheel) {
      append(far_.top().cycle, far_.top().item);
      far_.pop();
    }
  }
  Event take_at_cursor() {  // the first event at the cursor's cycle, which has one
    uint32_t slot = uint32_t(cursor_ % kWheel);
    Slot& s = slots_[slot];
    Event e{cursor_, s[s.next++]};
    if (s.next == s.count) {
      s.more.clear();  // keeps its capacity for the cycles to come
      s.next = s.count = 0;
      occupied_[slot / 64] &= ~(1ull << (slot % 64));
    }
    size_--;
    on_wheel_--;
    return e;
  }
  // Cycles from `from` to the next occupied wheel slot (kWheel if none), by the bitmap.
  uint32_t gap(Cycle from) const {
    uint32_t slot = uint32_t(from % kWheel);
    for (uint32_t scanned = 0; scanned < kWheel;) {
      uint64_t bits = occupied_[slot / 64] >> (slot % 64);
      if (bits) return scanned + uint32_t(__builtin_ctzll(bits));
      uint32_t step = 64 - slot % 64;
      scanned += step;
      slot = (slot + step) % kWheel;
    }
    return kWheel;
  }
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

// A unit's events: ray slots or warps at their cycles.
using EventQueue = Calendar<uint32_t>;

}  // namespace rtsim
