// Treelet queues in front of the RT units, after Aila & Karras, "Architecture Considerations
// for Tracing Incoherent Rays" (HPG 2010): the BVH is cut into treelets (model/bvh/treelets.h);
// a ray about to enter another treelet is postponed into that treelet's queue, and a unit that
// has free ray slots is given a batch of rays from one queue, so one treelet's nodes, fetched
// once into the unit's L1, serve every ray of the batch.
// Which queue: the policy's pick (treelet_policy.h) if it holds at least min_batch rays; else
// fresh rays from the dispatcher while the ray buffer (max_rays contexts: queued plus
// executing) has room; else the pick however short. A unit is never made to wait while some
// queue holds a ray. A full queue (queue_capacity) refuses a ray, which then keeps traversing
// in its unit.
// Timing: postponing takes enqueue_latency cycles and a taken ray steps dequeue_latency cycles
// after the take, or later when its state is still on its way from the ray buffer
// (ray_buffer.h), which also decides whether a ray may be postponed or fresh rays taken.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "model/sched/ray_buffer.h"
#include "model/sched/ray_supply.h"
#include "model/sched/treelet_policy.h"

namespace rtsim {

struct TreeletQueueConfig {
  std::string policy = "fullest";  // which queue is served next: fullest or oldest
  uint32_t max_rays = 8192;        // rays: ray buffer, queued plus executing
  uint32_t queue_capacity = 2048;  // rays: most rays one treelet's queue holds
  uint32_t min_batch = 32;         // rays: a queue this long is served before fresh rays
  uint32_t enqueue_latency = 2;    // cycles: from postponing a ray to it being queued
  uint32_t dequeue_latency = 2;    // cycles: from a take to the ray's next step
  RayBufferConfig buffer;
};

std::string treelet_queue_config_problem(const TreeletQueueConfig& config);

struct TreeletQueueStats {
  uint64_t visits = 0;            // batches handed out (treelet visits), fresh ones included
  uint64_t visit_rays = 0;        // rays in those batches
  uint64_t fresh_visits = 0;      // batches of fresh rays from the dispatcher
  uint64_t postponed = 0;         // rays queued
  uint64_t refused = 0;           // rays a full queue turned away
  uint64_t max_queued = 0;        // most rays queued at once, all queues
  uint64_t max_queue_length = 0;  // most rays in one queue
  double queued_ray_cycles = 0;   // integral of queued rays over time (mean = / cycles)
  Cycle last_change = 0;
};

class TreeletScheduler : public RaySupply {
 public:
  // upstream: the dispatcher (fresh rays, retirement); pool: the contexts it hands out;
  // state_bytes: one ray's state in the ray buffer.
  TreeletScheduler(const TreeletQueueConfig& config, uint32_t treelets,
                   std::vector<uint32_t> root_treelets, RaySupply& upstream,
                   const RayContextPool& pool, uint32_t state_bytes);

  size_t take(uint32_t unit, Cycle now, size_t max, std::vector<RayContext*>& out) override;
  bool postpone(RayContext& ray, uint32_t treelet, Cycle now) override;
  void retire(RayContext& ray, Cycle now) override;
  bool exhausted() const override;

  const TreeletQueueStats& stats() const { return stats_; }
  const RayBuffer& buffer() const { return buffer_; }
  uint64_t queued() const { return queued_; }
  uint64_t executing() const { return executing_; }
  // Counts the queue occupancy up to `now` (call once more at the end of a run).
  void account(Cycle now);

 private:
  size_t serve(uint32_t treelet, Cycle now, size_t max, std::vector<RayContext*>& out);
  void set_length(uint32_t treelet, uint32_t length);

  TreeletQueueConfig config_;
  std::vector<uint32_t> roots_;  // per frame (animated top levels); the last for later ones
  RaySupply& upstream_;
  const RayContextPool& pool_;
  std::unique_ptr<TreeletPolicy> policy_;
  std::vector<RayFifo> queues_;
  RayBuffer buffer_;
  uint64_t queued_ = 0, executing_ = 0;
  TreeletQueueStats stats_;
};

}  // namespace rtsim
