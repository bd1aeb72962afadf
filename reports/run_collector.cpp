#include "reports/run_collector.h"

#include <algorithm>
#include <cmath>

#include "model/sched/ray_context.h"

namespace rtsim::reports {

void RunCollector::retired(const RayContext& ray, Cycle now) {
  int type = int(ray.ray.type) % kRayTypeCount;
  uint64_t latency = now - std::min(now, ray.dispatched);
  int bin = latency == 0 ? 0 : int(std::log2(double(latency)) * kBinsPerOctave);
  bin = std::clamp(bin, 0, kLatencyBins - 1);
  if (latency_[type].empty()) latency_[type].assign(kLatencyBins, 0);
  latency_[type][size_t(bin)]++;
  while (now / bucket_cycles_ >= kMaxBuckets) widen();
  std::vector<uint64_t>& line = timeline_[type];
  size_t bucket = size_t(now / bucket_cycles_);
  if (line.size() <= bucket) line.resize(bucket + 1, 0);
  line[bucket]++;
}

void RunCollector::widen() {
  for (std::vector<uint64_t>& line : timeline_) {
    std::vector<uint64_t> merged((line.size() + 1) / 2, 0);
    for (size_t i = 0; i < line.size(); ++i) merged[i / 2] += line[i];
    line = merged;
  }
  bucket_cycles_ *= 2;
}

nlohmann::ordered_json RunCollector::to_json() const {
  nlohmann::ordered_json edges = nlohmann::ordered_json::array();
  for (int b = 0; b <= kLatencyBins; ++b) edges.push_back(std::exp2(double(b) / kBinsPerOctave));
  nlohmann::ordered_json counts = nlohmann::ordered_json::object();
  nlohmann::ordered_json retired = nlohmann::ordered_json::object();
  size_t buckets = 0;
  for (const auto& line : timeline_) buckets = std::max(buckets, line.size());
  for (int t = 0; t < kRayTypeCount; ++t) {
    if (latency_[t].empty()) continue;
    const char* name = ray_type_name(RayType(t));
    counts[name] = latency_[t];
    std::vector<uint64_t> line = timeline_[t];
    line.resize(buckets, 0);
    retired[name] = line;
  }
  return {{"latency_histogram", {{"edges", edges}, {"counts", counts}}},
          {"timeline", {{"bucket_cycles", bucket_cycles_}, {"retired", retired}}}};
}

}  // namespace rtsim::reports
