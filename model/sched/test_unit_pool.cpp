#include "model/sched/test_unit_pool.h"

#include <algorithm>
#include <stdexcept>

namespace rtsim {

std::string test_unit_config_problem(const TestUnitConfig& c) {
  if (c.count == 0 || c.count > 64) return "count must be 1..64";
  if (c.issue_width == 0 || c.issue_width > 64) return "issue_width must be 1..64";
  if (c.latency == 0 || c.latency > 10000) return "latency must be 1..10000";
  return {};
}

TestUnitPool::TestUnitPool(const TestUnitConfig& config)
    : config_(config), calendar_(kCalendarCycles) {
  std::string problem = test_unit_config_problem(config);
  if (!problem.empty()) throw std::invalid_argument(problem);
}

TestUnitPool::Slot* TestUnitPool::entry(Cycle cycle) {
  Slot& slot = calendar_[cycle & (kCalendarCycles - 1)];
  auto epoch = uint32_t(cycle / kCalendarCycles + 1);
  if (slot.epoch > epoch) return nullptr;
  if (slot.epoch < epoch) slot = Slot{epoch, 0, 0};  // an earlier cycle's entry: free again
  return &slot;
}

TestUnitPool::Slot* TestUnitPool::slot_at(Cycle cycle) {
  Slot* slot = entry(cycle);
  if (!slot) stats_.calendar_conflicts++;
  return slot;
}

TestUnitPool::Slot* TestUnitPool::find_free(Cycle& cycle) {
  constexpr int kPath = 32;
  struct Passed {
    Slot* slot;
    Cycle cycle;
  } path[kPath];
  int length = 0;
  Slot* slot;
  for (;;) {
    slot = slot_at(cycle);
    if (slot && slot->used < config_.count) break;
    if (slot && length < kPath) path[length++] = {slot, cycle};
    cycle += slot && slot->skip > 0 ? slot->skip : 1;
  }
  // Every booked cycle passed on the way now points (close to) here.
  for (int i = 0; i < length; ++i)
    path[i].slot->skip = uint16_t(std::min<Cycle>(cycle - path[i].cycle, kCalendarCycles - 1));
  return slot;
}

Cycle TestUnitPool::reserve_as(TestUnitPool& kind, Cycle arrival, uint32_t tests) {
  uint32_t width = kind.config_.issue_width, latency = kind.config_.latency;
  uint32_t issues = tests <= width ? 1 : (tests + width - 1) / width;  // most steps: one issue
  TestUnitStats& stats = kind.stats_;
  stats.requests++;
  stats.tests += tests;
  stats.issues += issues;
  if (issues == 1) {              // the common case: a unit free at the arrival cycle, no search
    Slot* slot = entry(arrival);  // a conflict is counted once, by the search below
    if (slot && slot->used < config_.count) {
      slot->used++;
      return arrival + latency;
    }
  }
  Cycle cycle = arrival;
  Slot* slot = find_free(cycle);
  stats.stall_cycles += cycle - arrival;
  for (;;) {
    uint32_t take = std::min<uint32_t>(config_.count - slot->used, issues);
    slot->used = uint16_t(slot->used + take);
    issues -= take;
    if (issues == 0) return cycle + latency;
    slot = find_free(++cycle);
  }
}

}  // namespace rtsim
