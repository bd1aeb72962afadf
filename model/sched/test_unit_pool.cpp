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

uint32_t& TestUnitPool::used_at(Cycle cycle) {
  Slot& slot = calendar_[cycle & (kCalendarCycles - 1)];
  if (slot.cycle != cycle) slot = Slot{cycle, 0};  // a past cycle's entry: free again
  return slot.used;
}

Cycle TestUnitPool::reserve(Cycle arrival, uint32_t tests) {
  uint32_t issues = (std::max<uint32_t>(tests, 1) + config_.issue_width - 1) / config_.issue_width;
  stats_.requests++;
  stats_.tests += tests;
  stats_.issues += issues;
  Cycle cycle = arrival, first = ~Cycle(0), last = arrival;
  while (issues > 0) {
    uint32_t& used = used_at(cycle);
    uint32_t take = std::min(config_.count - used, issues);
    if (take > 0) {
      if (first == ~Cycle(0)) first = cycle;
      used += take;
      issues -= take;
      last = cycle;
    }
    ++cycle;
  }
  stats_.stall_cycles += first - arrival;
  return last + config_.latency;
}

}  // namespace rtsim
