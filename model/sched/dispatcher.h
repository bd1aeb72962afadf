// Ray dispatcher: hands the rays of a stream to the RT units, `max` at a time (a warp in the
// per-ray and packet modes, a batch for the treelet queues), from a fixed pool of ray contexts,
// so rays in flight are bounded by the pool and never by the stream.
// Timing: the dispatcher delivers rays_per_cycle rays per cycle over one port (first come,
// first served), and a ray reaches its unit `latency` cycles after its delivery slot.
// Retired rays come back here and go to the listener (stats, verification) in retire order.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "model/sched/ray_source.h"
#include "model/sched/ray_supply.h"

namespace rtsim {

struct DispatchConfig {
  double rays_per_cycle = 4.0;  // rays/cycle: delivery bandwidth to all units together
  uint32_t latency = 8;         // cycles: from delivery to arrival at the unit
};

std::string dispatch_config_problem(const DispatchConfig& config);

struct DispatchStats {
  uint64_t rays = 0;         // rays handed out
  uint64_t retired = 0;      // rays given back finished
  uint64_t takes = 0;        // requests that received rays
  double busy_cycles = 0;    // cycles the delivery port was busy
  uint64_t wait_cycles = 0;  // sum over requests of first delivery - request
  uint64_t pool_empty = 0;   // requests cut short because every context was in use
};

class RayDispatcher : public RaySupply {
 public:
  RayDispatcher(const DispatchConfig& config, RaySource& source, RayContextPool& pool,
                RayRetireListener* listener);

  size_t take(uint32_t unit, Cycle now, size_t max, std::vector<RayContext*>& out) override;
  void retire(RayContext& ray, Cycle now) override;
  bool exhausted() const override { return !has_next_; }

  const DispatchStats& stats() const { return stats_; }
  uint64_t in_flight() const { return stats_.rays - stats_.retired; }
  // Called with every ray as it is handed out (the simulator marks warm-up and frames by it).
  void watch(std::function<void(const RayContext&)> watcher) { watcher_ = std::move(watcher); }

 private:
  void read_ahead();

  DispatchConfig config_;
  RaySource& source_;
  RayContextPool& pool_;
  RayRetireListener* listener_;
  std::function<void(const RayContext&)> watcher_;
  Ray next_;
  bool has_next_ = false;
  double port_free_ = 0;  // cycle (fractional) the delivery port is next free
  DispatchStats stats_;
};

}  // namespace rtsim
