#include "model/sched/rt_core.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "model/sched/ray_buffer.h"
#include "model/units/ray_box.h"

namespace rtsim {

const char* traversal_mode_name(TraversalMode mode) {
  switch (mode) {
    case TraversalMode::DepthFirst: return "depth_first";
    case TraversalMode::Treelet: return "treelet";
    case TraversalMode::Packet: return "packet";
  }
  return "?";
}

const char* refill_name(Refill refill) {
  return refill == Refill::Slot ? "slot" : "warp";
}

const char* test_issue_name(TestIssue issue) {
  return issue == TestIssue::Shared ? "shared" : "separate";
}

const char* packet_policy_name(PacketPolicy policy) {
  return policy == PacketPolicy::NodeFirst ? "node_first" : "majority";
}

std::string rt_core_config_problem(const RtCoreConfig& c) {
  if (c.warps == 0 || c.warps > 1024) return "warps must be 1..1024";
  if (c.warp_size == 0 || c.warp_size > 256) return "warp_size must be 1..256";
  if (c.issue_per_cycle == 0) return "issue_per_cycle must be at least 1";
  if (c.mode == TraversalMode::Packet && c.refill == Refill::Slot)
    return "refill = \"slot\" needs per-ray traversal: packet mode steps and refills whole warps";
  std::string problem = stack_config_problem(c.stack);
  if (!problem.empty()) return "stack: " + problem;
  problem = test_unit_config_problem(c.box);
  if (!problem.empty()) return "box: " + problem;
  problem = test_unit_config_problem(c.triangle);
  if (!problem.empty()) return "triangle: " + problem;
  if (c.test_issue == TestIssue::Shared && c.triangle.count != c.box.count)
    return "test_issue = \"shared\": triangle.count must equal box.count (one pool of units)";
  problem = test_unit_config_problem(c.transform);
  if (!problem.empty()) return "transform: " + problem;
  problem = test_unit_config_problem(c.anyhit.shader);
  if (!problem.empty()) return "any-hit shader: " + problem;
  const PrefetchConfig& p = c.prefetch;
  if (p.trigger != PrefetchTrigger::None && c.mode == TraversalMode::Packet)
    return "prefetch: needs per-ray traversal (depth_first or treelet), not packet mode";
  if (p.trigger == PrefetchTrigger::Batch && c.mode != TraversalMode::Treelet)
    return "prefetch: trigger = \"batch\" needs treelet queues (rt.mode = \"treelet\")";
  const PacketReorderConfig& r = c.reorder;
  if (!(r.below >= 0 && r.below <= 1)) return "packet: reorder_below must be 0..1";
  if (r.below > 0 && c.mode != TraversalMode::Packet)
    return "packet: reorder_below needs packet mode (rt.mode = \"packet\")";
  if (r.below > 0) {
    uint32_t runs = r.min_width ? c.warp_size / r.min_width : 0;
    if (runs == 0 || c.warp_size % r.min_width != 0 || (runs & (runs - 1)) != 0)
      return "packet: min_width must divide warp_size by a power of two (halving reaches it)";
  }
  if (p.recent == 0) return "prefetch: recent must be at least 1";
  if (p.batch_rays == 0) return "prefetch: batch_rays must be at least 1";
  return {};
}

RtCore::RtCore(uint32_t id, const RtCoreConfig& config, const TraversalUnit& traversal,
               MemoryTarget& memory, const TreeletFootprints* footprints)
    : id_(id),
      config_(config),
      traversal_(traversal),
      bvh_begin_(traversal.bvh().begin_address()),
      top_end_(traversal.bvh().top_end_address()),
      bvh_end_(traversal.bvh().end_address()),
      entry_treelets_(config.mode == TraversalMode::Treelet ||
                      config.prefetch.trigger == PrefetchTrigger::FirstVisit),
      memory_(memory),
      stack_(config.stack,
             config.mode == TraversalMode::Treelet ? 0 : config.warps * config.warp_size),
      state_bytes_(ray_state_bytes(config.stack, traversal.bvh().two_level())),
      box_(config.box),
      triangle_(config.triangle),
      transform_(config.transform),
      shader_(config.anyhit.shader),
      prefetcher_(config.prefetch, footprints) {
  std::string problem = rt_core_config_problem(config);
  if (!problem.empty()) throw std::invalid_argument(problem);
  if (config.prefetch.trigger != PrefetchTrigger::None && !footprints)
    throw std::invalid_argument("prefetch: the treelets' footprints are required");
  slots_.assign(size_t(config.warps) * config.warp_size, nullptr);
  warp_live_.assign(config.warps, 0);
  for (uint32_t w = config.warps; w-- > 0;) free_warps_.push_back(w);
  for (uint32_t s = uint32_t(slots_.size()); s-- > 0;) free_slots_.push_back(s);
  slot_state_.resize(slots_.size());
  lane_next_.resize(config.warp_size);
  if (config.mode == TraversalMode::Packet) {
    packet_unit_ = config.reorder.below > 0 ? config.reorder.min_width : config.warp_size;
    packet_head_.assign(slots_.size() / packet_unit_, 0);
    packet_width_.assign(slots_.size() / packet_unit_, config.warp_size);
  }
}

void RtCore::account(Cycle now) {
  if (now <= occupancy_since_) return;
  stats_.ray_slot_cycles += double(in_flight_) * double(now - occupancy_since_);
  occupancy_since_ = now;
}

uint64_t RtCore::poll(Cycle now) {
  now_ = std::max(now_, now);
  started_ = true;
  progress_ = 0;
  fill(now_);
  return progress_;
}

uint64_t RtCore::advance(Cycle until) {
  progress_ = 0;
  EventQueue::Event e;
  bool packet = config_.mode == TraversalMode::Packet;
  while (events_.pop_before(until, e)) {
    now_ = std::max(now_, e.cycle);
    if (packet) {
      on_packet(e.item, now_);
      continue;
    }
    prime_next_event();
    on_ray(e.item, now_);
  }
  return progress_;
}

void RtCore::prime_next_event() const {
  uint32_t slot;
  if (!events_.peek(slot)) return;
  // What on_ray reads first: the context up to the traversal state's counters, the slot's
  // control state, and the top of the stack (through the address noted after the ray's last
  // step: no load of the context).
  constexpr size_t kContextBytes = 384;
  prefetch_span<kHostL2>(slots_[slot], kContextBytes, 64);
  __builtin_prefetch(&slot_state_[slot], 0, kHostL2);
  __builtin_prefetch(slot_state_[slot].stack_top, 0, kHostL2);
}

Cycle RtCore::reserve_issue(Cycle now) {
  if (now > issue_cycle_) {
    issue_cycle_ = now;
    issued_ = 0;
  }
  if (issued_ == config_.issue_per_cycle) {
    ++issue_cycle_;
    issued_ = 0;
  }
  ++issued_;
  stats_.issues++;
  return issue_cycle_;
}

bool RtCore::claim_issue(uint32_t item, Cycle now) {
  if (slot_state_[item].issue_granted == now) {  // reserved earlier for this cycle
    slot_state_[item].issue_granted = ~Cycle(0);
    return true;
  }
  Cycle at = reserve_issue(now);
  if (at == now) return true;
  slot_state_[item].issue_granted = at;
  stats_.issue_stalls++;
  events_.push(at, item);
  return false;
}

RtCore::Next RtCore::peek(const TraversalState& s) const {
  // The entry step() will visit: the topmost one that may still hold a closer hit (the same
  // test step() makes, passing back to world space as it does; check_kind() catches a
  // disagreement).
  float t_hit = s.t_hit;
  bool top = s.level == s.top;
  for (size_t i = s.stack.size(); i-- > 0;) {
    const StackEntry& e = s.stack[i];
    if (e.count == kLeaveInstance) {
      t_hit = TraversalUnit::world_t_hit(s);
      top = true;
      continue;
    }
    if (e.tnear > t_hit * kSlabFarGrowth) continue;
    return {true, traversal_.kind_of(e, top), uint32_t(i)};
  }
  return {};
}

void RtCore::check_kind(const StepResult& step, const Next& next) const {
  if (step.kind == StepKind::Done ? next.live : !next.live || step.kind != next.kind)
    throw std::logic_error("rt" + std::to_string(id_) +
                           ": traversal visited another entry than the unit predicted; "
                           "RtCore::peek must apply the same cull test as TraversalUnit::step");
}

void RtCore::fill(Cycle now) {
  if (!supply_) throw std::logic_error("RtCore: no ray supply bound");
  waiting_ = false;
  bool per_warp = refills_warps();
  // Treelet mode takes a warp's worth of rays at a time; depth-first slot refill any number.
  uint32_t threshold = config_.mode == TraversalMode::Treelet
                           ? std::min<uint32_t>(config_.warp_size, uint32_t(slots_.size()))
                           : 1;
  while (per_warp ? !free_warps_.empty() : free_slots_.size() >= threshold) {
    size_t max = per_warp ? config_.warp_size : free_slots_.size();
    batch_.clear();
    size_t n = supply_->take(id_, now, max, batch_);
    if (n == 0) {
      waiting_ = !supply_->exhausted();
      return;
    }
    progress_ += n;
    if (per_warp) {
      uint32_t warp = free_warps_.back();
      free_warps_.pop_back();
      warp_live_[warp] = uint32_t(n);
      Cycle start = 0;
      for (size_t i = 0; i < n; ++i) {
        install(batch_[i], warp * config_.warp_size + uint32_t(i), now);
        start = std::max(start, batch_[i]->ready);
      }
      if (config_.mode == TraversalMode::Packet) {
        uint32_t runs = config_.warp_size / packet_unit_, head = warp * runs;
        std::fill_n(packet_head_.begin() + head, runs, head);
        packet_width_[head] = config_.warp_size;
        events_.push(std::max(start, now), head);
      }
    } else {
      for (RayContext* ray : batch_) {
        uint32_t slot = free_slots_.back();
        free_slots_.pop_back();
        install(ray, slot, now);
      }
      // A batch from one treelet's queue (fresh rays start at the root's treelet).
      if (config_.prefetch.trigger == PrefetchTrigger::Batch)
        prefetch(prefetcher_.on_batch(batch_[0]->treelet, uint32_t(n)), now);
    }
  }
}

void RtCore::install(RayContext* ray, uint32_t slot, Cycle now) {
  account(now);
  slots_[slot] = ray;
  ray->unit = id_;
  ray->slot = slot;
  in_flight_++;
  if (!ray->begun) {
    // Ray setup: the traversal state starts at the root, all of it on chip.
    traversal_.begin(ray->state, ray->ray);
    stack_.start(*ray);
    ray->entry_treelet.assign(1, traversal_.bvh().root_treelet(ray->ray.frame));
    ray->begun = true;
    ray->ready += config_.setup_latency;
    stats_.rays_started++;
  }
  if (config_.mode != TraversalMode::Packet) events_.push(std::max(ray->ready, now), slot);
}

void RtCore::release(uint32_t slot, Cycle now) {
  account(now);
  slots_[slot] = nullptr;
  in_flight_--;
  if (!refills_warps()) {
    free_slots_.push_back(slot);
  } else {
    uint32_t warp = slot / config_.warp_size;
    if (--warp_live_[warp] == 0) free_warps_.push_back(warp);
  }
  stats_.last_cycle = std::max(stats_.last_cycle, now);
}

void RtCore::retire(uint32_t slot, Cycle now) {
  RayContext* ray = slots_[slot];
  release(slot, now);
  stats_.rays_retired++;
  progress_++;
  supply_->retire(*ray, now);
}

std::string RtCore::dump() const {
  std::ostringstream out;
  out << "rt" << id_ << ": " << in_flight_ << " of " << slots_.size() << " ray slots busy, "
      << events_.size() << " events pending, " << waiting_reads_ << " reads waiting for data";
  if (!events_.empty()) out << " (next at cycle " << events_.next_cycle() << ")";
  out << ", local cycle " << now_ << (waiting_ ? ", waiting for rays" : "") << "\n";
  const int max_shown = 4;
  int busy = 0;
  for (const RayContext* ray : slots_) {
    if (!ray || ++busy > max_shown) continue;
    out << "  ray " << ray->sequence << " in slot " << ray->slot << ": stack "
        << ray->state.stack.size() << " (" << ray->residency.resident << " on chip, "
        << ray->residency.spilled << " spilled), " << ray->state.counters.trav_nodes
        << " nodes, ready at cycle " << ray->ready << "\n";
  }
  if (busy > max_shown) out << "  (" << busy - max_shown << " more rays)\n";
  return out.str();
}

}  // namespace rtsim
