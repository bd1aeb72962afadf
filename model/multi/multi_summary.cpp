#include "model/multi/multi_summary.h"

#include <algorithm>

namespace rtsim::multi {
namespace {

double mean(double sum, size_t count) {
  return count ? sum / double(count) : 0.0;
}

// Frames from `begin` until the deviation stays <= limit up to `end` (exclusive); -1 if the
// last frame before `end` is still above.
int settle_frames(const std::vector<FrameRecord>& frames, size_t begin, size_t end, double limit) {
  size_t settled = end;
  for (size_t f = end; f-- > begin;) {
    if (frames[f].max_deviation_pct > limit) break;
    settled = f;
  }
  return settled == end ? -1 : int(settled - begin);
}

}  // namespace

StrategySummary summarize(const StrategyRun& run, uint32_t devices,
                          const std::vector<uint32_t>& changes, double settle_pct) {
  StrategySummary s;
  s.strategy = run.strategy;
  const std::vector<FrameRecord>& frames = run.frames;
  s.frames = uint32_t(frames.size());
  s.avg_idle_pct.assign(devices, 0.0);
  if (frames.empty()) return s;
  size_t first = frames.size() > 1 ? 1 : 0;
  double dev = 0, dev_all = 0, speedup = 0, frame_ns = 0, single_ns = 0, overhead = 0, bytes = 0;
  for (size_t f = 0; f < frames.size(); ++f) {
    const FrameRecord& r = frames[f];
    dev_all += r.max_deviation_pct;
    if (f >= first) {
      dev += r.max_deviation_pct;
      s.worst_max_dev_pct = std::max(s.worst_max_dev_pct, r.max_deviation_pct);
    }
    speedup += r.speedup;
    frame_ns += r.timing.frame_ns;
    single_ns += r.single_ns;
    bytes += double(r.timing.copy_bytes);
    if (r.timing.frame_ns > 0) {
      overhead += 100.0 * r.timing.copy_overhead_ns / r.timing.frame_ns;
      for (uint32_t d = 0; d < devices && d < r.devices.size(); ++d)
        s.avg_idle_pct[d] += 100.0 * r.devices[d].timing.idle_ns / r.timing.frame_ns;
    }
  }
  size_t n = frames.size();
  s.avg_max_dev_pct = mean(dev, n - first);
  s.avg_max_dev_all_pct = mean(dev_all, n);
  s.avg_speedup = mean(speedup, n);
  s.avg_frame_ns = mean(frame_ns, n);
  s.avg_single_ns = mean(single_ns, n);
  s.avg_copy_overhead_pct = mean(overhead, n);
  s.avg_copy_bytes = mean(bytes, n);
  for (double& idle : s.avg_idle_pct) idle = mean(idle, n);
  std::vector<size_t> starts{0};
  for (uint32_t c : changes)
    for (size_t f = 1; f < n; ++f)
      if (frames[f].frame == c && starts.back() != f) starts.push_back(f);
  for (size_t i = 0; i < starts.size(); ++i) {
    size_t end = i + 1 < starts.size() ? starts[i + 1] : n;
    s.settle.push_back(
        {frames[starts[i]].frame, settle_frames(frames, starts[i], end, settle_pct)});
  }
  return s;
}

std::vector<uint32_t> change_frames(const MultiRunResult& result) {
  std::vector<uint32_t> changes;
  if (result.runs.empty()) return changes;
  const std::vector<FrameRecord>& frames = result.runs.front().frames;
  for (size_t f = 1; f < frames.size(); ++f) {
    for (size_t d = 0; d < frames[f].devices.size(); ++d) {
      if (frames[f].devices[d].hardware != frames[f - 1].devices[d].hardware) {
        changes.push_back(frames[f].frame);
        break;
      }
    }
  }
  return changes;
}

}  // namespace rtsim::multi
