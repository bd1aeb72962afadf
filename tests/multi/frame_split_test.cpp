// Frame splits (Harada & Fujita 2014): regions cover every pixel exactly once, shares follow
// n_i = t * p_i, and the CDF search puts each device's share in its region.
#include <gtest/gtest.h>

#include <numeric>
#include <random>

#include "model/multi/frame_split.h"

namespace rtsim::multi {
namespace {

// How many regions hold each pixel, found through the layout as the driver does.
std::vector<int> pixel_owners(const Split& split, const ScreenLayout& layout) {
  std::vector<int> owners(layout.pixels(), 0);
  for (uint32_t pixel = 0; pixel < layout.pixels(); ++pixel) {
    uint32_t p = layout.position_of(pixel);
    uint32_t d = device_at(split, p);
    EXPECT_GE(p, split[d].begin) << "pixel " << pixel;
    EXPECT_LT(p, split[d].end) << "pixel " << pixel;
    for (const Region& r : split) owners[pixel] += p >= r.begin && p < r.end;
  }
  return owners;
}

TEST(ScreenLayout, PositionsAndPixelsRoundTrip) {
  for (ScanOrder order : {ScanOrder::Rows, ScanOrder::Columns, ScanOrder::Interleaved})
    for (uint32_t height : {5u, 16u, 40u, 181u}) {
      ScreenLayout layout{7, height, order};
      std::vector<int> seen(layout.pixels(), 0);
      for (uint32_t pixel = 0; pixel < layout.pixels(); ++pixel) {
        uint32_t p = layout.position_of(pixel);
        ASSERT_LT(p, layout.pixels());
        EXPECT_EQ(layout.pixel_at(p), pixel) << scan_order_name(order) << " height " << height;
        ++seen[p];
      }
      for (int s : seen) EXPECT_EQ(s, 1) << "each position is one pixel's";
    }
  ScreenLayout columns{7, 5, ScanOrder::Columns};
  EXPECT_EQ(columns.position_of(1), 5u) << "pixel (1, 0) starts the second column";
  EXPECT_EQ(columns.position_of(7), 1u) << "pixel (0, 1) is second in the first column";
  // 40 rows, 17 apart: 0, 17, 34, 1, 18, 35, ..., 5, 22, 39, then 6, 23, ..., 16, 33.
  ScreenLayout interleaved{10, 40, ScanOrder::Interleaved};
  std::vector<uint32_t> rows;
  for (uint32_t p = 0; p < interleaved.pixels(); p += 10)
    rows.push_back(interleaved.pixel_at(p) / 10);
  EXPECT_EQ(std::vector<uint32_t>(rows.begin(), rows.begin() + 6),
            (std::vector<uint32_t>{0, 17, 34, 1, 18, 35}));
  EXPECT_EQ(rows[18], 6u) << "classes 0 to 5 hold 3 rows, the rest 2";
  EXPECT_EQ(rows.back(), 33u);
  Split quarter = equal_area_split(interleaved.pixels(), 4);
  uint32_t lowest = 40, highest = 0;
  for (uint32_t p = quarter[0].begin; p < quarter[0].end; ++p) {
    lowest = std::min(lowest, interleaved.pixel_at(p) / 10);
    highest = std::max(highest, interleaved.pixel_at(p) / 10);
  }
  EXPECT_EQ(lowest, 0u);
  EXPECT_EQ(highest, 36u) << "the first quarter of the positions spans the whole height";
}

TEST(EqualAreaSplit, CoversEveryPixelOnceWithEqualCounts) {
  for (uint32_t devices : {1u, 2u, 3u, 4u, 7u})
    for (uint32_t width : {1u, 5u, 64u}) {
      ScreenLayout layout{width, 9, ScanOrder::Rows};
      Split split = equal_area_split(layout.pixels(), devices);
      ASSERT_EQ(split.size(), devices);
      EXPECT_EQ(split_problem(split, layout.pixels()), "");
      for (int owners : pixel_owners(split, layout)) ASSERT_EQ(owners, 1);
      for (const Region& r : split) EXPECT_LE(r.size(), layout.pixels() / devices + 1);
      for (const Region& r : split) EXPECT_GE(r.size(), layout.pixels() / devices);
    }
}

TEST(EqualAreaSplit, MoreDevicesThanPixelsLeavesSomeEmpty) {
  Split split = equal_area_split(3, 5);
  EXPECT_EQ(split_problem(split, 3), "");
  EXPECT_EQ(split[3].size(), 0u);
  EXPECT_EQ(split[4].size(), 0u);
  EXPECT_EQ(device_at(split, 2), 2u);
}

TEST(BalancedShares, FollowIdealTimeTimesSpeed) {
  // t = N / sum(p) = 1000 / 10 = 100; n_i = t * p_i.
  std::vector<double> shares = balanced_shares({1, 2, 3, 4}, 1000);
  ASSERT_EQ(shares.size(), 4u);
  EXPECT_DOUBLE_EQ(shares[0], 100);
  EXPECT_DOUBLE_EQ(shares[1], 200);
  EXPECT_DOUBLE_EQ(shares[2], 300);
  EXPECT_DOUBLE_EQ(shares[3], 400);
  std::vector<double> one = balanced_shares({0.37}, 512);
  EXPECT_DOUBLE_EQ(one[0], 512) << "M = 1 gets everything";
  EXPECT_DOUBLE_EQ(balanced_shares({0, 5}, 10)[0], 0) << "a stopped device gets nothing";
  EXPECT_THROW(balanced_shares({0, 0}, 10), std::invalid_argument);
}

TEST(SplitByCdf, UniformWeightsGiveExactShares) {
  std::vector<double> weights(1000, 1.0);
  Split split = split_by_cdf(weights, balanced_shares({1, 2, 3, 4}, 1000));
  EXPECT_EQ(split_problem(split, 1000), "");
  EXPECT_EQ(split[0], (Region{0, 100}));
  EXPECT_EQ(split[1], (Region{100, 300}));
  EXPECT_EQ(split[2], (Region{300, 600}));
  EXPECT_EQ(split[3], (Region{600, 1000}));
}

TEST(SplitByCdf, IrregularCdfPutsEachShareInItsRegion) {
  std::mt19937 rng(7);
  std::gamma_distribution<double> sample_count(0.5, 4.0);  // irregular: many empty pixels
  ScreenLayout layout{48, 27, ScanOrder::Columns};
  std::vector<double> weights(layout.pixels());
  for (double& w : weights) w = std::floor(sample_count(rng));
  double total = std::accumulate(weights.begin(), weights.end(), 0.0);
  double heaviest = *std::max_element(weights.begin(), weights.end());
  std::vector<double> speeds{0.3, 1.0, 1.0, 2.5, 0.7};
  std::vector<double> shares = balanced_shares(speeds, total);
  Split split = split_by_cdf(weights, shares);
  EXPECT_EQ(split_problem(split, layout.pixels()), "");
  for (int owners : pixel_owners(split, layout)) ASSERT_EQ(owners, 1);
  // Each boundary is the nearest one on the CDF, so a region misses its share by at most one
  // pixel's weight at either end.
  for (size_t i = 0; i < split.size(); ++i) {
    double got =
        std::accumulate(weights.begin() + split[i].begin, weights.begin() + split[i].end, 0.0);
    EXPECT_NEAR(got, shares[i], heaviest) << "device " << i;
  }
}

TEST(SplitByCdf, DegenerateInputs) {
  std::vector<double> weights{0, 0, 5, 0, 0, 5, 0, 0};
  Split one = split_by_cdf(weights, {10});
  EXPECT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0], (Region{0, 8})) << "M = 1 takes the whole frame";
  Split zero_share = split_by_cdf(weights, {0, 10, 0});
  EXPECT_EQ(split_problem(zero_share, 8), "");
  std::vector<double> w = weights;
  EXPECT_EQ(zero_share[0].size(), 0u) << "a device with no share gets an empty region";
  EXPECT_EQ(std::accumulate(w.begin() + zero_share[2].begin, w.end(), 0.0), 0.0)
      << "the last device's share is 0: its region holds no weight";
  Split empty_frame = split_by_cdf(std::vector<double>(8, 0.0), {0, 0});
  EXPECT_EQ(split_problem(empty_frame, 8), "") << "no weight at all still covers the frame";
  Split no_pixels = split_by_cdf({}, {1, 1});
  EXPECT_EQ(split_problem(no_pixels, 0), "");
}

TEST(SplitProblem, NamesGapsAndOverlaps) {
  EXPECT_NE(split_problem({{0, 4}, {5, 8}}, 8), "");
  EXPECT_NE(split_problem({{0, 5}, {4, 8}}, 8), "");
  EXPECT_NE(split_problem({{0, 4}, {4, 7}}, 8), "");
  EXPECT_NE(split_problem({}, 8), "");
  EXPECT_EQ(split_problem({{0, 4}, {4, 4}, {4, 8}}, 8), "");
}

}  // namespace
}  // namespace rtsim::multi
