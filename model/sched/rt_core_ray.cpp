// RtCore, per-ray modes (depth-first and treelet queues), and the pieces of a step that the
// packet mode shares: reads with per-ray cost attribution, stack refills and spills.
#include <algorithm>

#include "model/sched/ray_buffer.h"
#include "model/sched/rt_core.h"

namespace rtsim {

uint32_t RtCore::level_of(uint64_t addr) const {
  if (addr >= bvh_begin_ && addr < bvh_end_)
    return top_end_ == bvh_begin_ ? 0 : addr < top_end_ ? 1 : 2;
  return addr >= kTextureBase && addr < kLocalMemoryBase ? 3 : 0;
}

void RtCore::charge_level(uint32_t level, const ReadCharge& charge) {
  if (level != 0)
    add_charge(level == 1 ? stats_.top : level == 2 ? stats_.bottom : stats_.texture, charge);
}

void RtCore::count_step(StepKind kind, const TraversalState& after) {
  switch (kind) {
    case StepKind::Node:
      stats_.node_steps++;
      if (after.level == after.top && traversal_.bvh().two_level()) stats_.top_node_steps++;
      break;
    case StepKind::Leaf: stats_.leaf_steps++; break;
    case StepKind::Instance: stats_.instance_steps++; break;
    case StepKind::Done: break;
  }
}

Cycle RtCore::read(RayContext& ray, uint64_t addr, uint32_t bytes, Cycle now, bool state) {
  ReadCharge charge;
  uint32_t level = level_of(addr);
  Cycle ready = memory_.read(addr, bytes, now, this, ray.slot | uint64_t(level) << 32, charge);
  add_charge(ray.cost, charge);
  if (state) add_charge(stats_.state, charge);
  charge_level(level, charge);
  stats_.fetches++;
  stats_.fetch_bytes += bytes;
  if (ready == kPending) {
    slot_state_[item_of(ray.slot)].pending_reads++;
    waiting_reads_++;
    stats_.waited_reads++;
  }
  return ready;
}

void RtCore::read_done(uint64_t token, Cycle ready, const ReadCharge& charge) {
  auto slot = uint32_t(token);
  add_charge(slots_[slot]->cost, charge);
  charge_level(uint32_t(token >> 32), charge);
  uint32_t item = item_of(slot);
  if (slot_state_[item].wait == Wait::State) add_charge(stats_.state, charge);
  slot_state_[item].data_ready = std::max(slot_state_[item].data_ready, ready);
  waiting_reads_--;
  if (--slot_state_[item].pending_reads > 0) return;
  Cycle at = slot_state_[item].data_ready;
  if (at < now_) {
    stats_.late_data++;
    stats_.late_cycles += now_ - at;
    at = now_;
  }
  Wait wait = slot_state_[item].wait;
  slot_state_[item].wait = Wait::None;
  if (wait == Wait::Data) {
    at = test_step(item, at);  // the test units keep a calendar: booked here, in any order
  } else {
    if (config_.mode != TraversalMode::Packet) slots_[item]->ready = at;
    events_.push(at, item);
  }
  data_event_ = std::min(data_event_, at);
}

bool RtCore::wait_reads(uint32_t item, Wait wait, Cycle known_ready) {
  if (slot_state_[item].pending_reads == 0) return false;
  slot_state_[item].wait = wait;
  slot_state_[item].data_ready = known_ready;
  return true;
}

Cycle RtCore::test_step(uint32_t item, Cycle data) {
  StepKind kind = slot_state_[item].kind;
  TestUnitPool& unit = kind == StepKind::Leaf   ? triangle_
                       : kind == StepKind::Node ? box_
                                                : transform_;
  // Shared issue slots: triangle tests take the box units' issues.
  TestUnitPool& issuer =
      kind == StepKind::Leaf && config_.test_issue == TestIssue::Shared ? box_ : unit;
  bool packet = config_.mode == TraversalMode::Packet;
  uint32_t first = packet ? item * packet_unit_ : item;
  uint32_t count = packet ? packet_width_[item] : 1;
  Cycle done = data;
  for (uint32_t slot = first; slot < first + count; ++slot) {
    if (slot_state_[slot].tests == kNoTests) continue;
    done =
        std::max(done, call_anyhit(slot, issuer.reserve_as(unit, data, slot_state_[slot].tests)));
    slot_state_[slot].tests = kNoTests;
  }
  Cycle next = done + config_.control_latency;
  if (config_.mode != TraversalMode::Packet) slots_[item]->ready = next;
  events_.push(next, item);
  return next;
}

Cycle RtCore::call_anyhit(uint32_t slot, Cycle tested) {
  uint32_t calls = slot_state_[slot].calls;
  if (calls == 0) return tested;
  slot_state_[slot].calls = 0;
  Cycle answered = tested;
  for (uint32_t i = 0; i < calls; ++i) answered = shader_.reserve(answered, 1);
  stats_.anyhit_calls += calls;
  stats_.anyhit_cycles += answered - tested;
  slots_[slot]->cost.anyhit_cycles += answered - tested;
  return answered;
}

void RtCore::read_texels(RayContext& ray, const StepResult& step, Cycle now, Cycle& known) {
  if (step.anyhit_calls == 0) return;  // call_anyhit left the slot's count at 0
  slot_state_[ray.slot].calls = step.anyhit_calls;
  for (uint64_t addr : ray.state.texels) {
    Cycle ready = read(ray, addr, config_.anyhit.read_bytes, now);
    if (ready != kPending) known = std::max(known, ready);
  }
  ray.state.texels.clear();
}

Cycle RtCore::fetch(RayContext& ray, const StepResult& step, Cycle now) {
  if (step.fetch_bytes == 0) return now;
  return read(ray, step.fetch_address, step.fetch_bytes, now);
}

bool RtCore::refill(RayContext& ray, const Next& next, Cycle now, Cycle& ready) {
  uint32_t pops = uint32_t(ray.state.stack.size()) - (next.live ? next.depth : 0);
  StackTransfer transfer = stack_.refill(ray, pops);
  if (transfer.bytes == 0) return false;
  stats_.refill_reads++;
  stats_.refill_entries += transfer.entries;
  Cycle data = read(ray, transfer.addr, transfer.bytes, now);
  if (data != kPending) ready = std::max(ready, data);
  return true;
}

void RtCore::load_state(RayContext& ray, Cycle now) {
  ray.state_in_memory = false;
  Cycle data = read(ray, ray_state_address(ray.id, state_bytes_), state_bytes_, now, true);
  Cycle ready = data == kPending ? now : std::max(now, data);
  if (wait_reads(ray.slot, Wait::State, ready)) return;
  ray.ready = ready;
  events_.push(ready, ray.slot);
}

void RtCore::prefetch(const std::vector<ByteRange>& ranges, Cycle now) {
  for (const ByteRange& r : ranges) memory_.prefetch(r.addr, r.bytes, now);
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
    stats_.spill_writes++;
    stats_.spill_entries += spill.entries;
  }
  if (!entry_treelets_) return;
  // The new entries belong to the visited node's treelet if they are leaves (or the way back
  // from an instance), else to their own, in the level the ray is in now.
  const BvhImage& level = *ray.state.level;
  ray.entry_treelet.resize(total);
  for (uint32_t i = kept; i < total; ++i)
    ray.entry_treelet[i] =
        stack[i].count == 0 ? node_treelet(level, stack[i].index) : visited_treelet;
}

void RtCore::on_ray(uint32_t slot, Cycle now) {
  RayContext& ray = *slots_[slot];
  // Traversal control starts issue_per_cycle steps a cycle.
  if (!claim_issue(slot, now)) return;
  if (ray.state_in_memory) {
    load_state(ray, now);
    return;
  }
  Next next = peek(ray.state);
  // Treelet mode: about to leave the treelet, the ray goes to the next treelet's queue.
  if (config_.mode == TraversalMode::Treelet && next.live) {
    uint32_t treelet = treelet_of(ray, next);
    if (treelet != ray.treelet) {
      if (supply_->postpone(ray, treelet, now)) {
        if (ray.state_in_memory)
          memory_.write(ray_state_address(ray.id, state_bytes_), state_bytes_, now);
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
    if (wait_reads(slot, Wait::Refill, ready)) return;
    ray.ready = ready;
    events_.push(ready, slot);
    return;
  }
  uint32_t visited_treelet = entry_treelets_ && next.live ? treelet_of(ray, next) : 0;
  // A node step prefetches on entering its treelet (after its own read).
  bool first_visit = config_.prefetch.trigger == PrefetchTrigger::FirstVisit;
  bool prefetch_node = first_visit && next.kind == StepKind::Node;
  StepResult step = traversal_.step(ray.state);
  check_kind(step, next);
  if (step.kind == StepKind::Done) {
    retire(slot, now);
    fill(now);
    return;
  }
  progress_++;
  Cycle data = fetch(ray, step, now);
  Cycle known = data == kPending ? now : data;
  read_texels(ray, step, now, known);
  if (prefetch_node) prefetch(prefetcher_.on_node(visited_treelet), now);
  count_step(step.kind, ray.state);
  settle(ray, next.depth, visited_treelet, now);
  slot_state_[slot].tests = step.tests ? step.tests : kNoTests;  // none: a masked instance
  slot_state_[slot].kind = step.kind;
  traversal_.prime(ray.state);
  if (!ray.state.stack.empty()) slot_state_[slot].stack_top = &ray.state.stack.back();
  if (!wait_reads(slot, Wait::Data, known)) test_step(slot, known);
}

}  // namespace rtsim
