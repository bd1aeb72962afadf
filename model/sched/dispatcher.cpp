#include "model/sched/dispatcher.h"

#include <algorithm>
#include <cmath>

namespace rtsim {

std::string dispatch_config_problem(const DispatchConfig& c) {
  if (!(c.rays_per_cycle > 0) || !std::isfinite(c.rays_per_cycle))
    return "rays_per_cycle must be positive";
  return {};
}

RayDispatcher::RayDispatcher(const DispatchConfig& config, RaySource& source, RayContextPool& pool,
                             RayRetireListener* listener)
    : config_(config), source_(source), pool_(pool), listener_(listener) {
  read_ahead();
}

void RayDispatcher::read_ahead() {
  has_next_ = source_.next(next_);
}

size_t RayDispatcher::take(uint32_t unit, Cycle now, size_t max, std::vector<RayContext*>& out) {
  size_t given = 0;
  double start = std::max(double(now), port_free_);
  while (given < max && has_next_) {
    RayContext* ray = pool_.acquire();
    if (!ray) {
      stats_.pool_empty++;
      break;
    }
    ray->ray = next_;
    ray->sequence = stats_.rays;
    ray->begun = false;
    ray->unit = unit;
    ray->cost = {};
    ray->next_in_queue = nullptr;
    // Deliveries are spaced 1 / rays_per_cycle apart on the port: rays_per_cycle a cycle.
    double slot = start + double(given) / config_.rays_per_cycle;
    ray->dispatched = ray->handed = Cycle(std::floor(slot));
    ray->ready = ray->dispatched + config_.latency;
    if (watcher_) watcher_(*ray);  // before it counts as handed out
    stats_.rays++;
    out.push_back(ray);
    ++given;
    read_ahead();
  }
  if (given > 0) {
    double length = double(given) / config_.rays_per_cycle;
    stats_.takes++;
    stats_.busy_cycles += length;
    stats_.wait_cycles += out[out.size() - given]->dispatched - now;  // the first delivery
    port_free_ = start + length;
  }
  return given;
}

void RayDispatcher::retire(RayContext& ray, Cycle now) {
  stats_.retired++;
  if (listener_) listener_->retired(ray, now);
  pool_.release(&ray);
}

}  // namespace rtsim
