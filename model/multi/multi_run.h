// M devices render each frame of a ray stream together, once per split strategy, and one
// device renders it alone for the speed-up (Harada & Fujita 2014; SEED's mGPU flow). Per frame
// and strategy: the policy proposes a split from what it saw before; each device traces the
// rays of the pixels in its region on its hardware
// of that frame; the flow model (mgpu_flow.h) adds ray generation, copies and filtering; the
// policy then observes each device's samples, cost and time.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "model/multi/device_backend.h"
#include "model/multi/device_set.h"
#include "model/multi/mgpu_flow.h"
#include "model/multi/split_policy.h"
#include "traces/stream.h"

namespace rtsim::multi {

struct DeviceFrame {
  Region region;
  uint32_t hardware = 0;                                   // index into DeviceConfigs::configs()
  uint64_t pixels = 0, samples = 0, rays = 0, cycles = 0;  // samples: camera rays
  double cost = 0;  // simulated cycles of its pixels' rays, summed
  DeviceTiming timing;
};

struct FrameRecord {
  uint32_t frame = 0;
  std::vector<DeviceFrame> devices;
  FrameTiming timing;
  double max_deviation_pct = 0;  // of the devices' tracing times
  double single_ns = 0;          // the frame on the primary's hardware alone
  double speedup = 0;            // single_ns / timing.frame_ns
};

struct StrategyRun {
  SplitStrategy strategy = SplitStrategy::Static;
  std::vector<FrameRecord> frames;
};

struct MultiRunResult {
  ScreenLayout layout;
  uint32_t devices = 0;
  uint64_t rays = 0;
  std::vector<double> single_trace_ns;  // per frame, the primary's hardware alone
  std::vector<StrategyRun> runs;        // in the set's strategy order
};

struct MultiRunOptions {
  uint32_t max_frames = 0;                                        // 0: every frame of the stream
  std::function<void(uint32_t frame, uint32_t frames)> progress;  // before each frame
};

MultiRunResult run_multi_device(RayStreamReader& reader, const DeviceSet& set,
                                DeviceConfigs& configs, DeviceBackend& backend,
                                const MultiRunOptions& options = {});

}  // namespace rtsim::multi
