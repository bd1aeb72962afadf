// Figures of one strategy over a run, as Harada & Fujita (2014) report them: the maximum
// deviation of the devices' tracing times from their mean, in %, averaged over frames; plus
// the speed-up against one device, the copy overhead, each device's idle share, and how many
// frames the split needs to settle after the start and after each hardware change. Frame 0
// has no previous frame, so no strategy has measured speeds for it (static splits it by area,
// the balancers on its own samples); averages of balancing leave it out (the *_all figures
// keep it).
#pragma once

#include <cstdint>
#include <vector>

#include "model/multi/multi_run.h"

namespace rtsim::multi {

struct SettleRecord {
  uint32_t frame = 0;      // the start (0) or a change of hardware
  int settle_frames = -1;  // frames until the deviation stays <= settle_pct; -1: it never does
};

struct StrategySummary {
  SplitStrategy strategy = SplitStrategy::Static;
  uint32_t frames = 0;
  double avg_max_dev_pct = 0;      // frames 1.. (frame 0 alone if there is only one)
  double avg_max_dev_all_pct = 0;  // every frame
  double worst_max_dev_pct = 0;    // frames 1..
  double avg_speedup = 0;          // mean of the per-frame speed-ups
  double avg_frame_ns = 0, avg_single_ns = 0;
  double avg_copy_overhead_pct = 0;  // mean of copy_overhead_ns / frame_ns
  double avg_copy_bytes = 0;
  std::vector<double> avg_idle_pct;  // per device: mean of idle_ns / frame_ns
  std::vector<SettleRecord> settle;  // frame 0 and every change inside the run
};

// changes: the frames where some device's hardware changes.
StrategySummary summarize(const StrategyRun& run, uint32_t devices,
                          const std::vector<uint32_t>& changes, double settle_pct);

// Frames (after the first) where some device's hardware differs from the frame before.
std::vector<uint32_t> change_frames(const MultiRunResult& result);

}  // namespace rtsim::multi
