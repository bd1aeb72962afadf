#include "model/mem/crossbar.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rtsim {

std::string crossbar_config_problem(const CrossbarConfig& c) {
  if (!(c.bytes_per_cycle >= 0) || !std::isfinite(c.bytes_per_cycle))
    return "bytes_per_cycle must be 0 (no limit) or positive";
  return {};
}

std::string slice_layout_problem(const CacheConfig& c, const SliceLayout& layout) {
  if (layout.slices == 0) return "slices must be at least 1";
  if (c.size_bytes % (uint64_t(layout.slices) * c.line_bytes * c.ways) != 0)
    return "size_bytes must be a multiple of slices * line_bytes * ways";
  return crossbar_config_problem(layout.crossbar);
}

Link::Link(double bytes_per_cycle) : capacity_(bytes_per_cycle) {
  if (capacity_ > 0) calendar_.resize(kCalendarCycles);
}

Cycle Link::search(Cycle at, uint32_t bytes) {
  double left = std::max<double>(bytes, 1e-9);
  Cycle cycle = at;
  bool started = false;
  for (;; ++cycle) {
    Slot* slot = entry(cycle);
    if (!slot) {
      stats_.calendar_conflicts++;
      continue;
    }
    double room = capacity_ - slot->used;
    if (room <= 1e-9) continue;
    if (!started) {
      stats_.stall_cycles += cycle - at;
      started = true;
    }
    double take = std::min(room, left);
    slot->used += take;
    left -= take;
    if (left <= 1e-9) return cycle;
  }
}

Crossbar::Crossbar(const CrossbarConfig& config, uint32_t slices)
    : config_(config), modelled_(config.latency > 0 || config.bytes_per_cycle > 0) {
  std::string problem = crossbar_config_problem(config);
  if (!problem.empty()) throw std::invalid_argument(problem);
  for (uint32_t s = 0; s < slices; ++s) {
    slice_in_.emplace_back(config.bytes_per_cycle);
    slice_out_.emplace_back(config.bytes_per_cycle);
  }
}

void Crossbar::add_units(uint32_t count) {
  while (unit_up_.size() < count) {
    unit_up_.emplace_back(config_.bytes_per_cycle);
    unit_down_.emplace_back(config_.bytes_per_cycle);
  }
}

Cycle Crossbar::cross(Link& from, Link& to, Cycle at, uint32_t bytes) {
  Cycle sent = from.transfer(at, bytes);
  return to.transfer(sent + config_.latency, bytes);
}

}  // namespace rtsim
