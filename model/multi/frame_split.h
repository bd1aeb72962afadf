// How M devices share the pixels of one frame (Harada & Fujita, "Ray tracing irregularly
// distributed samples on multiple GPUs", 2014): the frame buffer is split once per frame into
// M regions, each a contiguous run of pixels in a scan order (rows: horizontal strips with
// ragged ends; columns: vertical strips). A split is found by searching the cumulative
// distribution (CDF) of a per-pixel weight for each device's share: n_i = t * p_i with the
// ideal time t = N / sum(p_i), p_i the device's speed. Plain functions; no state.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rtsim::multi {

// Rows: pixel index order. Columns: column by column. Interleaved: row by row, but the rows
// taken kInterleaveStride apart (0, 17, 34, ..., then 1, 18, ...), so that any run of
// positions longer than a few rows holds rows from the whole height of the image (as 3dfx's
// scan-line interleave did): a region is then a sample of the frame, not a strip of it. The
// stride is odd so that work on power-of-two grids (tiles, surfel spawns) spreads over it.
enum class ScanOrder { Rows, Columns, Interleaved };
constexpr uint32_t kInterleaveStride = 17;
const char* scan_order_name(ScanOrder order);  // rows, columns, interleaved
std::optional<ScanOrder> scan_order_from_name(const std::string& name);

// The pixel grid and the order in which regions run over it. A "position" is a pixel's index
// in scan order; rays name pixels as y * width + x.
struct ScreenLayout {
  uint32_t width = 0, height = 0;
  ScanOrder order = ScanOrder::Rows;

  uint32_t pixels() const { return width * height; }
  uint32_t position_of(uint32_t pixel) const;  // pixel must be < pixels()
  uint32_t pixel_at(uint32_t position) const;
};

// Positions [begin, end) of one device; empty when begin == end.
struct Region {
  uint32_t begin = 0, end = 0;
  uint32_t size() const { return end - begin; }
  bool operator==(const Region& o) const { return begin == o.begin && end == o.end; }
};
using Split = std::vector<Region>;  // one region per device, in device order

// Equal pixel counts (the first positions % devices regions get one more). devices >= 1.
Split equal_area_split(uint32_t positions, uint32_t devices);

// n_i = t * p_i with t = total / sum(p_i): the work each device gets so that all finish at t.
// Speeds must be >= 0 with a positive sum; the shares sum to total.
std::vector<double> balanced_shares(const std::vector<double>& speeds, double total);

// The split whose regions hold the given shares of the weight, found on the CDF of weights
// (one weight >= 0 per position; the shares should sum to the total weight). Each boundary is
// the position whose CDF value is nearest to the sum of the shares before it.
Split split_by_cdf(const std::vector<double>& weights, const std::vector<double>& shares);

// The device whose region holds the position (regions must be contiguous from 0).
uint32_t device_at(const Split& split, uint32_t position);

// Why the split does not cover positions [0, positions) exactly once, in order; empty if fine.
std::string split_problem(const Split& split, uint32_t positions);

}  // namespace rtsim::multi
