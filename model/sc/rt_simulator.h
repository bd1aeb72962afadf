// The whole simulated machine for one run, built from a HwConfig:
//   dispatch -> [treelet_queues] -> rt0..rtN-1 (each with its own cache levels) -> mem (the
//   shared levels) -> dram
// plus the stall watchdog. The levels of the memory hierarchy meet at TLM-2.0 sockets; pass
// bind_memory to put another TLM memory model where the DRAM is: it binds the model to
// mem.out, loosely timed, or approximately timed after mem.use_timed_memory(lead)
// (model/mem/README.md, "Banked DRAM").
// SystemC allows one elaboration per process: build one RtSimulator per process (tests and
// benchmarks that compare runs use run_in_child(), model/sc/fork_run.h).
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "model/config/hw_config.h"
#include "model/sc/banked_dram_module.h"
#include "model/sc/dispatcher_module.h"
#include "model/sc/ray_sorter_module.h"
#include "model/sc/rt_unit_module.h"
#include "model/sc/shared_levels_module.h"
#include "model/sc/stall_watchdog.h"
#include "model/sc/tlm_memory.h"
#include "model/sc/treelet_queue_module.h"
#include "model/sched/sim_stats.h"
#include "model/sched/stats_registry.h"

namespace rtsim {

class RtSimulator {
 public:
  using MemoryBinder = std::function<void(SharedLevelsModule& l2)>;

  // width x height: the pixel grid of the rays (0 x 0: no pixel buffers). listener (optional)
  // also sees every retired ray, after the stats (the verifier).
  RtSimulator(const HwConfig& config, BvhView bvh, RaySource& source, uint32_t width = 0,
              uint32_t height = 0, RayRetireListener* listener = nullptr,
              MemoryBinder bind_memory = {});
  ~RtSimulator();

  // Runs to the end of the stream. Throws SimStallError (with a state dump), or rethrows what
  // a module threw (an InputError from a corrupt stream chunk, for example).
  void run();

  Cycle cycles() const;  // the cycle the last ray retired
  uint64_t rays() const { return collector_.rays(); }
  const SimStatsCollector& collected() const { return collector_; }
  const HwConfig& config() const { return config_; }
  CacheStats l2_stats() const;  // summed over the slices
  // A group or shared level's counters (level: an index into config().memory), summed over its
  // instances and slices; zero for a unit's own level.
  CacheStats level_stats(uint32_t level) const;
  // A shader model: what the SMs' shading reads cost, by the hit ray's type, over the units,
  // from the first measured ray on.
  std::array<ReadCounts, kRayTypeCount> shading_reads() const;
  // Before run(): each instance of the group or shared level `level` stands in for one of a
  // machine whose instances have 1 / own_share as many RT units, whose fetches are taken to last
  // first_fetch_cycles until the level has measured its own (Cache::share_first_references).
  void share_first_references(uint32_t level, double own_share, Cycle first_fetch_cycles);
  // During run(): an access of an RT unit this machine leaves out reaches its L2 (Cache::warm);
  // returns the blocks it fetched.
  uint32_t warm_l2(uint64_t addr, uint32_t bytes, bool write = false) {
    return shared_->warm(addr, bytes, write);
  }
  // Every counter under its dotted name, and the derived ratios; with a warm-up
  // (sim.warmup_rays, sim.warmup_frames) what accrued from the dispatch of the first measured
  // ray on ("cycles" too), the snapshot-and-subtract of ChampSim. Rays of the warm-up are left
  // out of the per-ray stats (collected()); work they still do after it counts.
  void report(StatsRegistry& stats) const;
  // Per frame of the measured part, from the dispatch of its first ray to that of the next
  // frame's (the last: to the end): its frame index, start cycle and stats (as report()).
  struct FrameStats {
    uint32_t frame = 0;
    Cycle start = 0;
    StatsRegistry stats;
  };
  std::vector<FrameStats> frame_stats() const;
  Cycle measured_from() const { return measure_start_; }
  std::string dump() const;  // every module's state

 private:
  void on_handed(const RayContext& ray);
  // The earliest cycle the L2 serves a queued request, the DRAM takes its next decision on the
  // requests it holds, or a unit has an event, such as data a read was promised (kPending:
  // none): what the stall watchdog waits for before calling a run stuck.
  Cycle next_delivery() const;
  void report_all(StatsRegistry& stats, Cycle end) const;  // the whole run's stats so far
  bool warmup() const { return config_.sim.warmup_rays > 0 || config_.sim.warmup_frames > 0; }

  HwConfig config_;
  Clock clock_;
  TraversalUnit traversal_;
  TreeletFootprints footprints_;  // the treelets' byte ranges, when the units prefetch
  RayContextPool pool_;
  SimStatsCollector collector_;
  RetireFanout fanout_;
  SimControl control_;
  std::unique_ptr<SharedLevelsModule> shared_;  // the group and shared levels, and the way to DRAM
  std::unique_ptr<DramModule> dram_;            // the simple DRAM, or
  std::unique_ptr<BankedDramModule> banked_dram_;  // the banked one
  std::unique_ptr<DispatcherModule> dispatch_;
  std::unique_ptr<TreeletQueueModule> treelets_;
  std::unique_ptr<RaySorterModule> sorter_;
  std::vector<std::unique_ptr<RtUnitModule>> units_;
  std::unique_ptr<StallWatchdog> watchdog_;
  bool measuring_ = false;  // the first measured ray has been handed toward a unit
  Cycle measure_start_ = 0;
  StatsRegistry before_measuring_;                          // the snapshot at measure_start_
  std::array<ReadCounts, kRayTypeCount> shading_before_{};  // and the shading reads' then
  std::vector<FrameStats> frame_marks_;  // per measured frame: the snapshot at its start
};

}  // namespace rtsim
