#include "model/sc/rt_simulator.h"

#include <algorithm>
#include <sstream>

#include <fmt/format.h>

#include "traces/error.h"

namespace rtsim {

namespace {

Clock clock_of(const HwConfig& c) {
  return Clock(sc_core::sc_time(1.0 / c.clock_ghz, sc_core::SC_NS));
}

}  // namespace

RtSimulator::RtSimulator(const HwConfig& config, BvhView bvh, RaySource& source, uint32_t width,
                         uint32_t height, RayRetireListener* listener, MemoryBinder bind_memory)
    : config_(config),
      clock_(clock_of(config)),
      traversal_(bvh, without_fetch_list()),
      pool_(ray_slots(config)),
      collector_(width, height, config.rt.warp_size) {
  fanout_.add(&collector_);
  if (listener) fanout_.add(listener);
  std::vector<MemoryLevelConfig> levels = levels_as_built(config);
  // A unit's last own level sends misses and writes after its tag check: the shared levels may
  // serve that far ahead.
  uint32_t own = own_levels(levels);
  shared_ = std::make_unique<SharedLevelsModule>(
      "mem", levels, config.rt_units, clock_, levels[own - 1].cache.hit_latency,
      [this](std::exception_ptr e) { control_.fail(e); });
  // Compulsory misses at every level; the BVH's blocks in bitmaps.
  uint64_t bvh_begin = bvh.begin_address(), bvh_end = bvh.end_address();
  shared_->track_cold_misses(bvh_begin, bvh_end);
  if (bind_memory) {
    bind_memory(*shared_);
  } else if (config.dram_model == DramModel::Banked) {
    banked_dram_ =
        std::make_unique<BankedDramModule>("dram", config.banked_dram, clock_, config.clock_ghz);
    // A lead beyond what the L2's window needs would only wake the DRAM more often.
    banked_dram_->set_response_lead(shared_->lookahead());
    shared_->connect_memory(*banked_dram_, banked_dram_->response_lead());
  } else {
    dram_ = std::make_unique<DramModule>("dram", config.dram, clock_);
    shared_->out.bind(dram_->in);
  }
  dispatch_ =
      std::make_unique<DispatcherModule>("dispatch", config.dispatch, source, pool_, &fanout_);
  collector_.measure_from(config.sim.warmup_rays, config.sim.warmup_frames);
  RaySupplyIf* supply = dispatch_.get();
  if (config.rt.mode == TraversalMode::Treelet) {
    treelets_ = std::make_unique<TreeletQueueModule>(
        "treelet_queues", config.treelet_queues, bvh.treelet_count(), bvh.root_treelets(), pool_,
        ray_state_bytes(config.rt.stack, bvh.two_level()));
    treelets_->in.bind(dispatch_->out);
    supply = treelets_.get();
  }
  if (config.sort.key != SortKey::None) {
    sorter_ = std::make_unique<RaySorterModule>("ray_sorter", config.sort,
                                                SceneBounds{bvh.top->scene_lo, bvh.top->scene_hi});
    sorter_->in.bind(dispatch_->out);
    supply = sorter_.get();
  }
  auto on_hand = [this](const RayContext& ray) { on_handed(ray); };
  if (sorter_)
    sorter_->on_leave(on_hand);
  else
    dispatch_->dispatcher().watch(on_hand);
  if (config.rt.prefetch.trigger != PrefetchTrigger::None) footprints_ = treelet_footprints(bvh);
  for (uint32_t i = 0; i < config.rt_units; ++i) {
    std::string name = "rt" + std::to_string(i);
    units_.push_back(std::make_unique<RtUnitModule>(name.c_str(), i, config.rt, levels, traversal_,
                                                    clock_, config.sim.quantum_cycles, control_,
                                                    &footprints_, config.shader));
    UnitMemory& memory = units_.back()->memory;
    for (uint32_t k = 0; k < memory.levels(); ++k)
      memory.level(k).track_cold_misses(bvh_begin, bvh_end);
    units_.back()->supply.bind(*supply);
    memory.connect(*shared_, i);
  }
  watchdog_ = std::make_unique<StallWatchdog>(
      "watchdog", config.sim.stall_cycles, clock_, control_, [this] { return next_delivery(); },
      [this] { return dump(); });
}

RtSimulator::~RtSimulator() = default;

void RtSimulator::run() {
  // sc_stop() ends a finished run; its "stopped by user" notice is not news.
  sc_core::sc_report_handler::set_actions(sc_core::SC_INFO, sc_core::SC_DO_NOTHING);
  sc_core::sc_start();
  collector_.finish();
  if (control_.error) std::rethrow_exception(control_.error);
  if (!control_.stall_report.empty()) throw SimStallError(control_.stall_report);
  if (control_.units_running > 0)
    throw SimStallError(
        "the simulation ran out of events with " + std::to_string(control_.units_running) +
        " units unfinished (a unit slept with nothing to wake it); state:\n" + dump());
  if (!measuring_)
    throw InputError(fmt::format(
        "[sim] warmup_rays = {} and warmup_frames = {} leave none of the stream's {} rays to "
        "measure",
        config_.sim.warmup_rays, config_.sim.warmup_frames, dispatch_->dispatcher().stats().rays));
}

void RtSimulator::on_handed(const RayContext& ray) {
  if (ray.sequence < config_.sim.warmup_rays || ray.ray.frame < config_.sim.warmup_frames) return;
  if (!measuring_) {
    measuring_ = true;
    measure_start_ = ray.handed;
    if (warmup()) {
      report_all(before_measuring_, ray.handed);
      shading_before_ = shading_reads();
    }
  }
  // A frame starts with its first ray (a sorting unit may still hand out the last frame's).
  if (!frame_marks_.empty() && frame_marks_.back().frame >= ray.ray.frame) return;
  FrameStats mark{ray.ray.frame, ray.handed, {}};
  if (frame_marks_.empty())
    mark.stats = before_measuring_;
  else
    report_all(mark.stats, ray.handed);
  frame_marks_.push_back(std::move(mark));
}

std::vector<RtSimulator::FrameStats> RtSimulator::frame_stats() const {
  std::vector<FrameStats> frames;
  for (size_t i = 0; i < frame_marks_.size(); ++i) {
    FrameStats f{frame_marks_[i].frame, frame_marks_[i].start, {}};
    if (i + 1 < frame_marks_.size())
      f.stats = frame_marks_[i + 1].stats;
    else
      report_all(f.stats, cycles());
    f.stats.subtract(frame_marks_[i].stats);
    frames.push_back(std::move(f));
  }
  return frames;
}

CacheStats RtSimulator::l2_stats() const {
  return shared_->instances()[0].stats();
}

std::array<ReadCounts, kRayTypeCount> RtSimulator::shading_reads() const {
  ShaderStats sum;
  for (const auto& unit : units_)
    if (unit->shader()) sum += unit->shader()->stats();
  for (int t = 0; t < kRayTypeCount; ++t) sum.reads[t] -= shading_before_[t];
  return sum.reads;
}

CacheStats RtSimulator::level_stats(uint32_t level) const {
  CacheStats sum;
  auto [begin, end] = shared_->instances_of(level);
  for (uint32_t i = begin; i < end; ++i) sum += shared_->instances()[i].stats();
  return sum;
}

void RtSimulator::share_first_references(uint32_t level, double own_share,
                                         Cycle first_fetch_cycles) {
  shared_->share_first_references(level, own_share, first_fetch_cycles);
}

Cycle RtSimulator::cycles() const {
  Cycle last = collector_.last_retire();
  for (const auto& unit : units_) {
    last = std::max(last, unit->core().stats().last_cycle);
    if (unit->shader()) last = std::max(last, unit->shader()->stats().last_cycle);
  }
  return last;
}

Cycle RtSimulator::next_delivery() const {
  Cycle now = clock_.cycles(sim_now()), next = shared_->next_job();
  if (banked_dram_) next = std::min(next, banked_dram_->next_wake());
  for (const auto& unit : units_) {
    if (unit->core().has_event()) next = std::min(next, unit->core().next_event());
    if (unit->shader()) next = std::min(next, unit->shader()->next_wake(now));
  }
  return next;
}

std::string RtSimulator::dump() const {
  std::ostringstream out;
  const RayDispatcher& d = dispatch_->dispatcher();
  out << "dispatch: " << d.stats().rays << " rays handed out, " << d.in_flight()
      << " in flight, stream " << (d.exhausted() ? "exhausted" : "has rays") << "\n";
  if (treelets_) out << treelets_->dump();
  if (sorter_) out << sorter_->dump();
  const size_t shown = 20;
  for (const auto& unit : units_) {
    out << unit->core().dump();
    if (unit->shader()) out << unit->shader()->dump();
    const UnitMemory& memory = unit->memory;
    for (uint32_t k = 0; k < memory.levels(); ++k) {
      std::vector<Cache::WaitingRead> reads = memory.level(k).waiting();
      for (size_t i = 0; i < std::min(shown, reads.size()); ++i)
        out << "  " << unit->name() << "." << shared_->levels()[k].name << ": read of 0x"
            << std::hex << reads[i].addr << std::dec << origin_text(reads[i].origin)
            << " waits for " << (reads[i].for_mshr ? "an MSHR" : "the level below")
            << " since cycle " << reads[i].since << "\n";
      if (reads.size() > shown) out << "  (" << reads.size() - shown << " more reads)\n";
    }
  }
  out << "shared levels: " << shared_->queued()
      << " requests, answers and DRAM accesses queued, next at cycle " << shared_->next_job()
      << "\n"
      << shared_->waiting(shown);
  if (banked_dram_)
    out << "dram: " << banked_dram_->controller().queued() << " bursts queued, next decision "
        << banked_dram_->next_event() << ", taken at cycle " << banked_dram_->next_wake() << "\n";
  return out.str();
}

}  // namespace rtsim
