// RtCore, packet mode: the rays of a warp step together (SIMT). Each warp step picks a step
// kind (packet_policy); the lanes whose next visit is of that kind are active, the others
// idle. Active lanes fetch at once, and fetches of the same address in one warp step are
// coalesced into one read; their tests pass the unit pool one lane after another. The warp
// steps again when the slowest active lane is done. SIMD efficiency = active lanes / lanes.
// A warp starts as one packet; with packet reordering (PacketReorderConfig) it may go on as
// narrower packets, each stepping on its own, until all its rays retire and it refills.
#include <algorithm>
#include <stdexcept>

#include "model/sched/rt_core.h"

namespace rtsim {

void RtCore::on_packet(uint32_t item, Cycle now) {
  if (!claim_issue(item, now)) return;
  uint32_t base = item * packet_unit_, width = packet_width_[item];
  // What each lane visits next; a lane with nothing left retires now.
  uint32_t nodes = 0, leaves = 0;
  for (uint32_t lane = 0; lane < width; ++lane) {
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
    fill(now);  // the packet is done; once its warp's packets all are, the warp refills
    return;
  }
  bool leaf_step = config_.packet_policy == PacketPolicy::NodeFirst ? nodes == 0 : leaves > nodes;
  // Regroup only when lanes of the other kind would idle: empty lanes cost nothing here.
  uint32_t stepping = leaf_step ? leaves : nodes;
  if (width > config_.reorder.min_width && stepping < nodes + leaves &&
      stepping < config_.reorder.below * width) {
    reorder(item, leaf_step, now);
    return;
  }
  auto active = [&](uint32_t lane) {
    return slots_[base + lane] && lane_next_[lane].leaf == leaf_step;
  };
  // Spilled entries the active lanes need come back first; the warp waits for them.
  Cycle ready = now;
  bool refilled = false;
  for (uint32_t lane = 0; lane < width; ++lane)
    if (active(lane)) refilled |= refill(*slots_[base + lane], lane_next_[lane], now, ready);
  if (refilled) {
    if (wait_reads(item, Wait::Refill, ready)) return;
    events_.push(ready, item);
    return;
  }
  // Step the active lanes; one read per distinct address.
  warp_reads_.clear();
  Cycle data = now;
  uint32_t count = 0;
  for (uint32_t lane = 0; lane < width; ++lane) {
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
  step_leaf_[item] = leaf_step;
  progress_ += count;
  (leaf_step ? stats_.leaf_steps : stats_.node_steps) += count;
  stats_.warp_steps++;
  stats_.active_lanes += count;
  stats_.packet_lanes += width;
  if (!leaf_step) {
    stats_.node_warp_steps++;
    stats_.distinct_nodes += warp_reads_.size();
  }
  if (!wait_reads(item, Wait::Data, data)) test_step(item, data);
}

void RtCore::reorder(uint32_t item, bool leaf_step, Cycle now) {
  if (pending_reads_[item] > 0)
    throw std::logic_error("RtCore: regrouping a packet with reads out");
  uint32_t base = item * packet_unit_, width = packet_width_[item];
  regroup_.clear();
  for (uint32_t lane = 0; lane < width; ++lane) {
    RayContext* ray = slots_[base + lane];
    if (!ray) continue;
    const Next& next = lane_next_[lane];
    regroup_.push_back({ray, next.leaf != leaf_step, ray->state.stack[next.depth].index, lane});
  }
  std::sort(regroup_.begin(), regroup_.end(), [](const Regroup& a, const Regroup& b) {
    if (a.other_kind != b.other_kind) return b.other_kind;
    return a.node != b.node ? a.node < b.node : a.lane < b.lane;
  });
  for (uint32_t lane = 0; lane < width; ++lane) {
    RayContext* ray = lane < regroup_.size() ? regroup_[lane].ray : nullptr;
    slots_[base + lane] = ray;
    if (ray) ray->slot = base + lane;
  }
  uint32_t half = width / 2, second = item + half / packet_unit_;
  packet_width_[item] = packet_width_[second] = half;
  std::fill_n(packet_head_.begin() + second, half / packet_unit_, second);
  stats_.reorders++;
  events_.push(now + config_.reorder.latency, item);
  if (regroup_.size() > half) events_.push(now + config_.reorder.latency, second);
}

}  // namespace rtsim
