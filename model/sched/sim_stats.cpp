#include "model/sched/sim_stats.h"

#include <algorithm>
#include <stdexcept>

namespace rtsim {

SimStatsCollector::SimStatsCollector(uint32_t width, uint32_t height, uint32_t warp_size)
    : warp_size_(std::max<uint32_t>(warp_size, 1)) {
  pixels_.width = width;
  pixels_.height = height;
  size_t n = size_t(width) * height;
  pixels_.cycles.assign(n, 0.0f);
  pixels_.nodes.assign(n, 0.0f);
  pixels_.dram_bytes.assign(n, 0.0f);
}

void SimStatsCollector::retired(const RayContext& ray, Cycle now) {
  last_retire_ = std::max(last_retire_, now);
  if (ray.sequence < first_sequence_ || ray.ray.frame < first_frame_) return;
  auto type = uint8_t(size_t(ray.ray.type) % kRayTypeCount);
  RayTypeStats& s = by_type_[type];
  const RayCost& cost = ray.cost;
  uint64_t latency = now - std::min(now, ray.dispatched);
  s.rays++;
  s.hits += ray.state.prim != kNoHit;
  s.counters += ray.state.counters;
  s.reads += cost.reads;
  s.stack_spills += cost.stack_spills;
  s.stack_refills += cost.stack_refills;
  s.postponed += cost.postponed;
  s.anyhit_cycles += cost.anyhit_cycles;
  s.latency.add(latency);
  rays_++;
  Warp& warp = warps_[ray.sequence / warp_size_];
  warp.first_dispatch = std::min(warp.first_dispatch, ray.dispatched);
  warp.last_retire = std::max(warp.last_retire, now);
  if (ray.sequence < warp.first_sequence) {
    warp.first_sequence = ray.sequence;
    warp.type = type;
  }
  if (++warp.retired == warp_size_) {
    close(warp);
    warps_.erase(ray.sequence / warp_size_);
  }
  if (pixels_.cycles.empty()) return;
  if (ray.ray.pixel >= pixels_.cycles.size())  // the stream's reader refuses such rays
    throw std::logic_error("a retired ray's pixel lies outside the pixel buffers");
  pixels_.cycles[ray.ray.pixel] += float(latency);
  pixels_.nodes[ray.ray.pixel] += float(ray.state.counters.trav_nodes);
  pixels_.dram_bytes[ray.ray.pixel] += float(cost.reads.dram_bytes);
}

void SimStatsCollector::close(const Warp& warp) {
  by_type_[warp.type].warp_latency.add(warp.last_retire -
                                       std::min(warp.last_retire, warp.first_dispatch));
}

void SimStatsCollector::finish() {
  for (const auto& entry : warps_) close(entry.second);
  warps_.clear();
}

}  // namespace rtsim
