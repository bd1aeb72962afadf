#include "model/sched/hardware_stack.h"

namespace rtsim {

std::string stack_config_problem(const StackConfig& c) {
  if (c.entries == 0 || c.entries > 4096) return "entries must be 1..4096";
  if (c.entry_bytes == 0 || c.entry_bytes > 64) return "entry_bytes must be 1..64";
  return {};
}

StackTransfer HardwareStack::refill(RayContext& ray, uint32_t pops) const {
  uint32_t need = ray.residency.refill(pops);
  if (need == 0) return {};
  ray.cost.stack_refills += need;
  return {address(ray, ray.residency.spilled), need * config_.entry_bytes, need};
}

StackTransfer HardwareStack::settle(RayContext& ray, uint32_t kept, uint32_t total) const {
  uint32_t out = ray.residency.settle(kept, total, config_.entries);
  if (out == 0) return {};
  ray.cost.stack_spills += out;
  return {address(ray, ray.residency.spilled - out), out * config_.entry_bytes, out};
}

}  // namespace rtsim
