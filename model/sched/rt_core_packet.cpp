// RtCore, packet mode: the rays of a warp step together (SIMT). Each warp step picks a step
// kind (packet_policy: node_first takes nodes while any lane has one, then the more needed of
// leaves and instance transforms; majority the most needed kind); the lanes whose next visit is of
// that kind are active, the others idle. Active lanes fetch at once, and fetches of the same
// address in one warp step are coalesced into one read; their tests pass the unit pool one lane
// after another. The warp steps again when the slowest active lane is done. SIMD efficiency =
// active lanes / lanes. A warp starts as one packet; with packet reordering (PacketReorderConfig)
// it may go on as narrower packets, each stepping on its own, until all its rays retire and it
// refills.
#include <algorithm>
#include <stdexcept>

#include "model/sched/rt_core.h"

namespace rtsim {
namespace {

// The kind of a packet step, from the lanes that need each kind (node, leaf, instance).
StepKind packet_kind(PacketPolicy policy, const uint32_t (&lanes)[3]) {
  auto most = [&](StepKind a, StepKind b) { return lanes[int(b)] > lanes[int(a)] ? b : a; };
  if (policy == PacketPolicy::NodeFirst && lanes[int(StepKind::Node)] > 0) return StepKind::Node;
  StepKind best = most(StepKind::Leaf, StepKind::Instance);
  return policy == PacketPolicy::NodeFirst ? best : most(StepKind::Node, best);
}

}  // namespace

void RtCore::on_packet(uint32_t item, Cycle now) {
  if (!claim_issue(item, now)) return;
  uint32_t base = item * packet_unit_, width = packet_width_[item];
  // What each lane visits next; a lane with nothing left retires now.
  uint32_t lanes[3] = {0, 0, 0}, live = 0;  // by kind: node, leaf, instance
  for (uint32_t lane = 0; lane < width; ++lane) {
    RayContext* ray = slots_[base + lane];
    if (!ray) continue;
    Next& next = lane_next_[lane];
    next = peek(ray->state);
    if (next.live) {
      lanes[int(next.kind)]++;
      live++;
      continue;
    }
    check_kind(traversal_.step(ray->state), next);
    retire(base + lane, now);
  }
  if (live == 0) {
    fill(now);  // the packet is done; once its warp's packets all are, the warp refills
    return;
  }
  StepKind kind = packet_kind(config_.packet_policy, lanes);
  // Regroup only when lanes of another kind would idle: empty lanes cost nothing here.
  uint32_t stepping = lanes[int(kind)];
  if (width > config_.reorder.min_width && stepping < live &&
      stepping < config_.reorder.below * width) {
    reorder(item, kind, now);
    return;
  }
  auto active = [&](uint32_t lane) { return slots_[base + lane] && lane_next_[lane].kind == kind; };
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
    slot_state_[base + lane].tests = kNoTests;
    if (!active(lane)) continue;
    RayContext& ray = *slots_[base + lane];
    StepResult step = traversal_.step(ray.state);
    check_kind(step, lane_next_[lane]);
    ++count;
    count_step(step.kind, ray.state);
    slot_state_[base + lane].tests = step.tests ? step.tests : kNoTests;
    if (step.fetch_bytes > 0) {
      uint64_t addr = step.fetch_address;
      if (std::find(warp_reads_.begin(), warp_reads_.end(), addr) == warp_reads_.end()) {
        warp_reads_.push_back(addr);
        Cycle ready = fetch(ray, step, now);
        if (ready != kPending) data = std::max(data, ready);
      }
    }
    read_texels(ray, step, now, data);
    settle(ray, lane_next_[lane].depth, 0, now);
  }
  slot_state_[item].kind = kind;
  progress_ += count;
  stats_.warp_steps++;
  stats_.active_lanes += count;
  stats_.packet_lanes += width;
  if (kind == StepKind::Node) {
    stats_.node_warp_steps++;
    stats_.distinct_nodes += warp_reads_.size();
  }
  if (!wait_reads(item, Wait::Data, data)) test_step(item, data);
}

void RtCore::reorder(uint32_t item, StepKind kind, Cycle now) {
  if (slot_state_[item].pending_reads > 0)
    throw std::logic_error("RtCore: regrouping a packet with reads out");
  uint32_t base = item * packet_unit_, width = packet_width_[item];
  regroup_.clear();
  for (uint32_t lane = 0; lane < width; ++lane) {
    RayContext* ray = slots_[base + lane];
    if (!ray) continue;
    const Next& next = lane_next_[lane];
    regroup_.push_back({ray, next.kind != kind, ray->state.stack[next.depth].index, lane});
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
