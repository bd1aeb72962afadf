// A distribution of latencies (of rays, of DRAM requests) in constant memory: exact below 1024
// cycles, then 64 bins per power of two (values within 1.6% of each other share a bin). Percentiles
// come out as the upper end of their bin, never above the largest value seen.
#pragma once

#include <cstdint>
#include <vector>

namespace rtsim {

class LatencyHistogram {
 public:
  LatencyHistogram();
  void add(uint64_t cycles);
  uint64_t count() const { return count_; }
  uint64_t max() const { return max_; }
  uint64_t sum() const { return sum_; }
  double mean() const { return count_ ? double(sum_) / double(count_) : 0.0; }
  // The smallest bin bound below which at least fraction p of the values lie (0 if empty).
  uint64_t percentile(double p) const;

 private:
  std::vector<uint64_t> bins_;
  uint64_t count_ = 0, sum_ = 0, max_ = 0;
};

}  // namespace rtsim
