// RtCore, per-ray modes (depth-first and treelet queues), and the pieces of a step that the
// packet mode shares: reads with per-ray cost attribution, stack refills and spills.
#include <algorithm>

#include "model/sched/rt_core.h"

namespace rtsim {

Cycle RtCore::read(RayContext& ray, uint64_t addr, uint32_t bytes, Cycle now) {
  // The call chain through L1, L2 and DRAM is synchronous: the counters' growth during it is
  // exactly this read's doing.
  const CacheStats* l1 = probe_.l1;
  const CacheStats* l2 = probe_.l2;
  uint64_t l1_accesses = l1 ? l1->accesses : 0, l1_hits = l1 ? l1->hits : 0;
  uint64_t l1_below = l1 ? l1->bytes_below : 0;
  uint64_t l2_accesses = l2 ? l2->accesses : 0, l2_hits = l2 ? l2->hits : 0;
  uint64_t l2_below = l2 ? l2->bytes_below : 0;
  Cycle ready = memory_.read(addr, bytes, now);
  if (l1) {
    ray.cost.l1_accesses += uint32_t(l1->accesses - l1_accesses);
    ray.cost.l1_hits += uint32_t(l1->hits - l1_hits);
    if (!l2) ray.cost.dram_bytes += l1->bytes_below - l1_below;
  }
  if (l2) {
    ray.cost.l2_accesses += uint32_t(l2->accesses - l2_accesses);
    ray.cost.l2_hits += uint32_t(l2->hits - l2_hits);
    ray.cost.dram_bytes += l2->bytes_below - l2_below;
  }
  stats_.fetches++;
  stats_.fetch_bytes += bytes;
  return ready;
}

Cycle RtCore::fetch(RayContext& ray, const StepResult& step, Cycle now) {
  if (step.access_count == 0) return now;
  // A node is one record; a leaf's triangles are contiguous, so one read covers them.
  const MemoryAccess& first = ray.state.accesses[step.first_access];
  const MemoryAccess& last = ray.state.accesses[step.first_access + step.access_count - 1];
  uint32_t bytes = uint32_t(last.address + last.bytes - first.address);
  return read(ray, first.address, bytes, now);
}

bool RtCore::refill(RayContext& ray, const Next& next, Cycle now, Cycle& ready) {
  uint32_t pops = uint32_t(ray.state.stack.size()) - (next.live ? next.depth : 0);
  StackTransfer transfer = stack_.refill(ray, pops);
  if (transfer.bytes == 0) return false;
  stats_.refill_reads++;
  stats_.refill_entries += transfer.entries;
  ready = std::max(ready, read(ray, transfer.addr, transfer.bytes, now));
  return true;
}

uint32_t RtCore::treelet_of(const RayContext& ray, const Next& next) const {
  return ray.entry_treelet[next.depth];
}

void RtCore::settle(RayContext& ray, uint32_t kept, uint32_t visited_treelet, Cycle now) {
  const std::vector<StackEntry>& stack = ray.state.stack;
  uint32_t total = uint32_t(stack.size());
  kept = std::min(kept, total);  // an any-hit query clears the stack on its hit
  StackTransfer spill = stack_.settle(ray, kept, total);
  if (spill.bytes > 0) {
    memory_.write(spill.addr, spill.bytes, now);
    ray.cost.dram_bytes += spill.bytes;  // spills are written around the caches
    stats_.spill_writes++;
    stats_.spill_entries += spill.entries;
  }
  if (config_.mode != TraversalMode::Treelet) return;
  // The new entries belong to the visited node's treelet if they are leaves, else to their own.
  ray.entry_treelet.resize(total);
  for (uint32_t i = kept; i < total; ++i)
    ray.entry_treelet[i] = stack[i].count == 0 ? node_treelet_[stack[i].index] : visited_treelet;
}

void RtCore::on_ray(uint32_t slot, Cycle now) {
  RayContext& ray = *slots_[slot];
  // Traversal control starts issue_per_cycle steps a cycle.
  if (!claim_issue(slot, now)) return;
  Next next = peek(ray.state);
  // Treelet mode: about to leave the treelet, the ray goes to the next treelet's queue.
  if (config_.mode == TraversalMode::Treelet && next.live) {
    uint32_t treelet = treelet_of(ray, next);
    if (treelet != ray.treelet) {
      if (supply_->postpone(ray, treelet, now)) {
        stats_.postponed++;
        progress_++;
        release(slot, now);
        fill(now);
        return;
      }
      stats_.refused++;
      ray.treelet = treelet;
    }
  }
  // Entries spilled earlier come back before the step can pop them.
  Cycle ready = now;
  if (refill(ray, next, now, ready)) {
    ray.ready = ready;
    events_.push(ready, slot);
    return;
  }
  bool treelets = config_.mode == TraversalMode::Treelet;
  uint32_t visited_treelet = treelets && next.live ? treelet_of(ray, next) : 0;
  StepResult step = traversal_.step(ray.state);
  check_kind(step, next);
  if (step.kind == StepKind::Done) {
    retire(slot, now);
    fill(now);
    return;
  }
  progress_++;
  Cycle data = fetch(ray, step, now);
  TestUnitPool& unit = step.kind == StepKind::Node ? box_ : triangle_;
  Cycle done = unit.reserve(data, step.tests);
  (step.kind == StepKind::Node ? stats_.node_steps : stats_.leaf_steps)++;
  settle(ray, next.depth, visited_treelet, now);
  ray.state.accesses.clear();
  ray.ready = done + config_.control_latency;
  events_.push(ray.ready, slot);
}

}  // namespace rtsim
