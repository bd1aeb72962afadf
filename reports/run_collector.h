// What a report needs from a simulation beyond its stats JSON, gathered from every retired ray:
// the full latency distribution per ray type (log-spaced bins, 4 per octave) and a timeline of
// retirements per ray type (buckets that double in width so there are never more than
// kMaxBuckets). Constant memory whatever the stream length.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/sched/ray_supply.h"

namespace rtsim::reports {

class RunCollector : public RayRetireListener {
 public:
  static constexpr int kBinsPerOctave = 4;
  static constexpr int kLatencyBins = 26 * kBinsPerOctave;  // up to 2^26 cycles
  static constexpr size_t kMaxBuckets = 200;

  void retired(const RayContext& ray, Cycle now) override;

  // {"latency_histogram": {"edges": [...], "counts": {type: [...]}},
  //  "timeline": {"bucket_cycles": B, "retired": {type: [...]}}}; only types with rays.
  nlohmann::ordered_json to_json() const;

 private:
  void widen();

  std::array<std::vector<uint64_t>, kRayTypeCount> latency_{};
  std::array<std::vector<uint64_t>, kRayTypeCount> timeline_{};
  uint64_t bucket_cycles_ = 64;
};

}  // namespace rtsim::reports
