// What the simulation learns from every retired ray: per ray type, counters (rays, traversal
// counters under Embree's names, cache accesses and hits charged to the ray, DRAM bytes, stack
// traffic), the latency distribution of its rays and of its warps; per pixel, buffers of cycles,
// nodes visited and DRAM bytes for heatmaps. Plain counters; ratios are derived when written
// (model/sc/sim_report.h). Memory: fixed per ray type, plus three floats per pixel of the stream's
// image.
#pragma once

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "model/mem/latency_histogram.h"
#include "model/sched/ray_supply.h"

namespace rtsim {

struct RayTypeStats {
  uint64_t rays = 0, hits = 0;
  TraversalCounters counters;  // trav_nodes, trav_leaves, trav_prims, trav_prim_hits
  ReadCounts reads;            // block accesses and hits at each cache level, DRAM bytes
  uint64_t stack_spills = 0, stack_refills = 0, postponed = 0;
  uint64_t anyhit_cycles = 0;  // cycles waiting for any-hit calls
  LatencyHistogram latency;    // cycles from dispatch to retirement
  // Warps: warp_size consecutive rays of the stream, as a shader core issues them; a warp waits
  // from its first ray's dispatch to its last ray's retirement. A warp counts for the type of
  // its first ray.
  LatencyHistogram warp_latency;
};

constexpr uint64_t kPixelBufferBytes = 3 * sizeof(float);  // a pixel's cycles, nodes, DRAM bytes

struct PixelBuffers {
  uint32_t width = 0, height = 0;
  std::vector<float> cycles, nodes, dram_bytes;  // row-major, summed over a pixel's rays
};

class SimStatsCollector : public RayRetireListener {
 public:
  // width x height: the stream's pixel grid (0 x 0: no pixel buffers); warp_size: rays per warp.
  SimStatsCollector(uint32_t width, uint32_t height, uint32_t warp_size);
  void retired(const RayContext& ray, Cycle now) override;
  // The end of the stream: counts the warps left short (the last one, one cut by the warm-up).
  void finish();
  // Rays before stream position `sequence` or of frames before `frame` are a warm-up: they
  // count for last_retire() only.
  void measure_from(uint64_t sequence, uint32_t frame) {
    first_sequence_ = sequence;
    first_frame_ = frame;
  }

  const std::array<RayTypeStats, kRayTypeCount>& by_type() const { return by_type_; }
  const PixelBuffers& pixels() const { return pixels_; }
  uint64_t rays() const { return rays_; }
  Cycle last_retire() const { return last_retire_; }

 private:
  std::array<RayTypeStats, kRayTypeCount> by_type_;
  PixelBuffers pixels_;
  uint64_t rays_ = 0;
  Cycle last_retire_ = 0;
  uint64_t first_sequence_ = 0;
  uint32_t first_frame_ = 0;
  // Warps with rays still in flight, by warp number (sequence / warp size).
  struct Warp {
    Cycle first_dispatch = ~Cycle(0), last_retire = 0;
    uint64_t first_sequence = ~uint64_t(0);
    uint32_t retired = 0;
    uint8_t type = 0;
  };
  void close(const Warp& warp);
  uint32_t warp_size_;
  std::unordered_map<uint64_t, Warp> warps_;
};

// Several listeners in turn.
class RetireFanout : public RayRetireListener {
 public:
  void add(RayRetireListener* listener) { listeners_.push_back(listener); }
  void retired(const RayContext& ray, Cycle now) override {
    for (RayRetireListener* l : listeners_) l->retired(ray, now);
  }

 private:
  std::vector<RayRetireListener*> listeners_;
};

}  // namespace rtsim
