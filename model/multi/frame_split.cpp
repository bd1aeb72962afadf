#include "model/multi/frame_split.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include <fmt/format.h>

namespace rtsim::multi {

const char* scan_order_name(ScanOrder order) {
  switch (order) {
    case ScanOrder::Rows: return "rows";
    case ScanOrder::Columns: return "columns";
    case ScanOrder::Interleaved: return "interleaved";
  }
  return "?";
}

std::optional<ScanOrder> scan_order_from_name(const std::string& name) {
  for (ScanOrder o : {ScanOrder::Rows, ScanOrder::Columns, ScanOrder::Interleaved})
    if (name == scan_order_name(o)) return o;
  return std::nullopt;
}

namespace {

// Interleaved rows: row y is in class y % S, and classes come one after another, each in
// increasing y. Classes below H % S hold one row more than the others.
uint32_t interleaved_rank(uint32_t y, uint32_t height) {
  uint32_t c = y % kInterleaveStride, q = height / kInterleaveStride;
  uint32_t r = height % kInterleaveStride;
  return c * q + std::min(c, r) + y / kInterleaveStride;
}

uint32_t interleaved_row(uint32_t rank, uint32_t height) {
  uint32_t q = height / kInterleaveStride, r = height % kInterleaveStride;
  uint32_t c, i;
  if (rank < r * (q + 1)) {
    c = rank / (q + 1);
    i = rank % (q + 1);
  } else {
    c = r + (rank - r * (q + 1)) / q;
    i = (rank - r * (q + 1)) % q;
  }
  return c + i * kInterleaveStride;
}

}  // namespace

uint32_t ScreenLayout::position_of(uint32_t pixel) const {
  switch (order) {
    case ScanOrder::Rows: return pixel;
    case ScanOrder::Columns: return (pixel % width) * height + pixel / width;
    case ScanOrder::Interleaved:
      return interleaved_rank(pixel / width, height) * width + pixel % width;
  }
  return pixel;
}

uint32_t ScreenLayout::pixel_at(uint32_t position) const {
  switch (order) {
    case ScanOrder::Rows: return position;
    case ScanOrder::Columns: return (position % height) * width + position / height;
    case ScanOrder::Interleaved:
      return interleaved_row(position / width, height) * width + position % width;
  }
  return position;
}

Split equal_area_split(uint32_t positions, uint32_t devices) {
  if (devices == 0) throw std::invalid_argument("equal_area_split: no devices");
  Split split(devices);
  uint32_t base = positions / devices, extra = positions % devices, begin = 0;
  for (uint32_t i = 0; i < devices; ++i) {
    uint32_t size = base + (i < extra ? 1 : 0);
    split[i] = {begin, begin + size};
    begin += size;
  }
  return split;
}

std::vector<double> balanced_shares(const std::vector<double>& speeds, double total) {
  double sum = std::accumulate(speeds.begin(), speeds.end(), 0.0);
  if (!(sum > 0)) throw std::invalid_argument("balanced_shares: speeds must have a positive sum");
  double ideal_time = total / sum;  // t = N / sum(p_i)
  std::vector<double> shares;
  for (double p : speeds) shares.push_back(ideal_time * p);  // n_i = t * p_i
  return shares;
}

Split split_by_cdf(const std::vector<double>& weights, const std::vector<double>& shares) {
  if (shares.empty()) throw std::invalid_argument("split_by_cdf: no devices");
  auto positions = uint32_t(weights.size());
  // cdf[j]: the weight of positions [0, j).
  std::vector<double> cdf(weights.size() + 1, 0.0);
  std::partial_sum(weights.begin(), weights.end(), cdf.begin() + 1);
  Split split(shares.size());
  uint32_t begin = 0;
  double target = 0;
  for (size_t i = 0; i + 1 < shares.size(); ++i) {
    target += shares[i];
    auto it = std::lower_bound(cdf.begin(), cdf.end(), target);
    auto end = uint32_t(std::min<ptrdiff_t>(it - cdf.begin(), positions));
    if (end > 0 && target - cdf[end - 1] < cdf[end] - target) --end;  // the nearer boundary
    end = std::max(end, begin);
    split[i] = {begin, end};
    begin = end;
  }
  split.back() = {begin, positions};
  return split;
}

uint32_t device_at(const Split& split, uint32_t position) {
  auto it = std::upper_bound(split.begin(), split.end(), position,
                             [](uint32_t p, const Region& r) { return p < r.end; });
  if (it == split.end()) return uint32_t(split.size() - 1);
  return uint32_t(it - split.begin());
}

std::string split_problem(const Split& split, uint32_t positions) {
  if (split.empty()) return "no regions";
  uint32_t next = 0;
  for (size_t i = 0; i < split.size(); ++i) {
    const Region& r = split[i];
    if (r.begin != next) return fmt::format("region {} starts at {}, not at {}", i, r.begin, next);
    if (r.end < r.begin) return fmt::format("region {} ends before it starts", i);
    next = r.end;
  }
  if (next != positions) return fmt::format("regions end at {}, not at {}", next, positions);
  return "";
}

}  // namespace rtsim::multi
