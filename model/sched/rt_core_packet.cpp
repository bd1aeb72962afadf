// RtCore, packet mode: the rays of a warp step together (SIMT). Each warp step picks a step
// kind (packet_policy); the lanes whose next visit is of that kind are active, the others
// idle. Active lanes fetch at once, and fetches of the same address in one warp step are
// coalesced into one read; their tests pass the unit pool one lane after another. The warp
// steps again when the slowest active lane is done. SIMD efficiency = active lanes / lanes.
#include <algorithm>

#include "model/sched/rt_core.h"

namespace rtsim {

void RtCore::on_warp(uint32_t warp, Cycle now) {
  if (!claim_issue(warp, now)) return;
  uint32_t base = warp * config_.warp_size;
  // What each lane visits next; a lane with nothing left retires now.
  uint32_t nodes = 0, leaves = 0;
  for (uint32_t lane = 0; lane < config_.warp_size; ++lane) {
    RayContext* ray = slots_[base + lane];
    if (!ray) continue;
    Next& next = lane_next_[lane];
    next = peek(ray->state);
    if (next.live) {
      (next.leaf ? leaves : nodes)++;
      continue;
    }
    check_kind(traversal_.step(ray->state), next);
    retire(base + lane, now);
  }
  if (nodes + leaves == 0) {
    fill(now);  // the warp is done: its slot takes new rays
    return;
  }
  bool leaf_step = config_.packet_policy == PacketPolicy::NodeFirst ? nodes == 0 : leaves > nodes;
  auto active = [&](uint32_t lane) {
    return slots_[base + lane] && lane_next_[lane].leaf == leaf_step;
  };
  // Spilled entries the active lanes need come back first; the warp waits for them.
  Cycle ready = now;
  bool refilled = false;
  for (uint32_t lane = 0; lane < config_.warp_size; ++lane)
    if (active(lane)) refilled |= refill(*slots_[base + lane], lane_next_[lane], now, ready);
  if (refilled) {
    if (wait_reads(warp, Wait::Refill, ready)) return;
    events_.push(ready, warp);
    return;
  }
  // Step the active lanes; one read per distinct address.
  warp_reads_.clear();
  Cycle data = now;
  uint32_t count = 0;
  for (uint32_t lane = 0; lane < config_.warp_size; ++lane) {
    step_tests_[base + lane] = kNoTests;
    if (!active(lane)) continue;
    RayContext& ray = *slots_[base + lane];
    StepResult step = traversal_.step(ray.state);
    check_kind(step, lane_next_[lane]);
    ++count;
    step_tests_[base + lane] = step.tests;
    if (step.access_count > 0) {
      uint64_t addr = ray.state.accesses[step.first_access].address;
      if (std::find(warp_reads_.begin(), warp_reads_.end(), addr) == warp_reads_.end()) {
        warp_reads_.push_back(addr);
        Cycle ready = fetch(ray, step, now);
        if (ready != kPending) data = std::max(data, ready);
      }
    }
    settle(ray, lane_next_[lane].depth, 0, now);
    ray.state.accesses.clear();
  }
  step_leaf_[warp] = leaf_step;
  progress_ += count;
  (leaf_step ? stats_.leaf_steps : stats_.node_steps) += count;
  stats_.warp_steps++;
  stats_.active_lanes += count;
  if (!leaf_step) {
    stats_.node_warp_steps++;
    stats_.distinct_nodes += warp_reads_.size();
  }
  if (!wait_reads(warp, Wait::Data, data)) test_step(warp, data);
}

}  // namespace rtsim
