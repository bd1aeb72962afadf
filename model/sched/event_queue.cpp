#include "model/sched/event_queue.h"

#include <algorithm>
#include <stdexcept>

namespace rtsim {

EventQueue::EventQueue() : head_(kWheel, kNone), tail_(kWheel, kNone) {}

void EventQueue::append(Cycle cycle, uint32_t item) {
  uint32_t node;
  if (free_ != kNone) {
    node = free_;
    free_ = nodes_[node].next;
  } else {
    node = uint32_t(nodes_.size());
    nodes_.emplace_back();
  }
  nodes_[node] = {item, kNone};
  uint32_t slot = uint32_t(cycle % kWheel);
  occupied_[slot / 64] |= 1ull << (slot % 64);
  if (tail_[slot] == kNone)
    head_[slot] = node;
  else
    nodes_[tail_[slot]].next = node;
  tail_[slot] = node;
  on_wheel_++;
}

void EventQueue::push(Cycle cycle, uint32_t item) {
  if (cycle < cursor_) throw std::logic_error("EventQueue: event scheduled in the past");
  size_++;
  if (cycle < cursor_ + kWheel)
    append(cycle, item);
  else
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
  while (head_[cursor_ % kWheel] == kNone) {
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

bool EventQueue::pop_before(Cycle until, Event& event) {
  if (size_ == 0) return false;
  // Events left at the cursor's cycle (several in one cycle) need no scan for the next one.
  Cycle next = on_wheel_ > 0 && head_[cursor_ % kWheel] != kNone ? cursor_ : next_cycle();
  if (next >= until) return false;
  if (next != cursor_) {  // turn the wheel to it, as settle() would, without a second scan
    cursor_ = next;
    pull_far();
  }
  event = pop();
  return true;
}

EventQueue::Event EventQueue::pop() {
  settle();
  uint32_t slot = uint32_t(cursor_ % kWheel);
  uint32_t node = head_[slot];
  head_[slot] = nodes_[node].next;
  if (head_[slot] == kNone) {
    tail_[slot] = kNone;
    occupied_[slot / 64] &= ~(1ull << (slot % 64));
  }
  Event e{cursor_, nodes_[node].item};
  nodes_[node].next = free_;
  free_ = node;
  size_--;
  on_wheel_--;
  return e;
}

}  // namespace rtsim
