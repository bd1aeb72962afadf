#include "model/mem/latency_histogram.h"

#include <algorithm>
#include <cmath>

namespace rtsim {
namespace {

constexpr uint64_t kExact = 1024;  // values below are their own bin
constexpr int kSubBits = 6;        // 64 bins per power of two above

int top_bit(uint64_t v) {
  return 63 - __builtin_clzll(v);
}

size_t bin_of(uint64_t v) {
  if (v < kExact) return size_t(v);
  int e = top_bit(v);
  uint64_t sub = (v >> (e - kSubBits)) & ((1u << kSubBits) - 1);
  return kExact + size_t(e - 10) * (1u << kSubBits) + sub;
}

uint64_t bin_upper(size_t bin) {
  if (bin < kExact) return bin;
  size_t i = bin - kExact;
  int e = int(i >> kSubBits) + 10;
  uint64_t sub = i & ((1u << kSubBits) - 1);
  uint64_t lower = ((1ull << kSubBits) + sub) << (e - kSubBits);
  return lower + (1ull << (e - kSubBits)) - 1;
}

}  // namespace

LatencyHistogram::LatencyHistogram() : bins_(kExact + (64 - 10) * (1u << kSubBits), 0) {}

void LatencyHistogram::add(uint64_t cycles) {
  bins_[bin_of(cycles)]++;
  count_++;
  sum_ += cycles;
  max_ = std::max(max_, cycles);
}

uint64_t LatencyHistogram::percentile(double p) const {
  if (count_ == 0) return 0;
  auto need = uint64_t(std::ceil(p * double(count_)));
  need = std::clamp<uint64_t>(need, 1, count_);
  uint64_t seen = 0;
  for (size_t bin = 0; bin < bins_.size(); ++bin) {
    seen += bins_[bin];
    if (seen >= need) return std::min(bin_upper(bin), max_);
  }
  return max_;
}

}  // namespace rtsim
