#include "model/sched/hardware_stack.h"

#include <algorithm>

namespace rtsim {

std::string stack_config_problem(const StackConfig& c) {
  if (c.entries == 0 || c.entries > 4096) return "entries must be 1..4096";
  if (c.entry_bytes == 0 || c.entry_bytes > 64) return "entry_bytes must be 1..64";
  return {};
}

StackTransfer HardwareStack::refill(RayContext& ray, uint32_t pops) const {
  if (pops <= ray.resident || ray.spilled == 0) return {};
  uint32_t need = std::min(ray.spilled, pops - ray.resident);
  ray.spilled -= need;
  ray.resident += need;
  ray.cost.stack_refills += need;
  return {address(ray, ray.spilled), need * config_.entry_bytes, need};
}

StackTransfer HardwareStack::settle(RayContext& ray, uint32_t kept, uint32_t total) const {
  // Spilled entries are the oldest, so they survive first.
  ray.spilled = std::min({ray.spilled, kept, total});
  ray.resident = total - ray.spilled;
  if (ray.resident <= config_.entries) return {};
  uint32_t out = ray.resident - config_.entries;
  StackTransfer write{address(ray, ray.spilled), out * config_.entry_bytes, out};
  ray.spilled += out;
  ray.resident = config_.entries;
  ray.cost.stack_spills += out;
  return write;
}

}  // namespace rtsim
