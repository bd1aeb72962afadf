#include "model/sched/event_queue.h"

#include <algorithm>
#include <stdexcept>

namespace rtsim {

EventQueue::EventQueue() : slots_(kWheel) {}

void EventQueue::throw_past() {
  throw std::logic_error("EventQueue: event scheduled in the past");
}

void EventQueue::push_far(Cycle cycle, uint32_t item) {
  far_.push({cycle, far_order_++, item});
}

// Cycles from `from` to the next occupied wheel slot (kWheel if none), by the bitmap.
uint32_t EventQueue::gap(Cycle from) const {
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

// Far events that came within reach of the cursor join the wheel, in their order.
void EventQueue::pull_far() {
  while (!far_.empty() && far_.top().cycle < cursor_ + kWheel) {
    append(far_.top().cycle, far_.top().item);
    far_.pop();
  }
}

void EventQueue::settle() {
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

Cycle EventQueue::next_cycle() const {
  if (on_wheel_ == 0) return far_.top().cycle;
  return cursor_ + gap(cursor_);
}

bool EventQueue::turn_before(Cycle until, Event& event) {
  Cycle next = next_cycle();
  if (next >= until) return false;
  cursor_ = next;  // turn the wheel to it, as settle() would, without a second scan
  pull_far();
  event = take_at_cursor();
  return true;
}

EventQueue::Event EventQueue::pop() {
  settle();
  return take_at_cursor();
}

}  // namespace rtsim
