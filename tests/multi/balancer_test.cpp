// The split policies: static stays equal-area; the Harada & Fujita balancer turns the previous
// frame's speeds p_i = work / time and its CDF into shares n_i = t * p_i; degenerate frames
// (a device with zero time, an empty frame, M = 1) leave a valid split.
#include <gtest/gtest.h>

#include <numeric>

#include "model/multi/split_policy.h"

namespace rtsim::multi {
namespace {

double weight_of(const std::vector<double>& w, const Region& r) {
  return std::accumulate(w.begin() + r.begin, w.begin() + r.end, 0.0);
}

// A finished frame: the policy's split, each device's samples taken from the map, its time
// from the given speed (samples per ns); the cost map is `cost_factor` times the samples.
FrameFeedback frame_with_speeds(const SplitPolicy& policy, const std::vector<double>& samples,
                                const std::vector<double>& speeds, double cost_factor = 3.0) {
  FrameFeedback f;
  f.split = policy.next_split();
  f.samples = samples;
  for (double& c : f.cost = samples) c *= cost_factor;
  for (size_t i = 0; i < speeds.size(); ++i) {
    double n = weight_of(samples, f.split[i]);
    f.devices.push_back({n, n * cost_factor, n > 0 ? n / speeds[i] : 0.0});
  }
  return f;
}

std::vector<double> irregular_samples(uint32_t positions) {
  std::vector<double> s(positions);
  for (uint32_t i = 0; i < positions; ++i) s[i] = 1 + (i * 7919 % 13 == 0 ? 9 : i % 3);
  return s;
}

TEST(StaticSplit, StaysEqualAreaWhateverItObserves) {
  auto policy = make_split_policy(SplitStrategy::Static, 4, 1000);
  Split first = policy->next_split();
  EXPECT_EQ(first, equal_area_split(1000, 4));
  policy->observe(frame_with_speeds(*policy, irregular_samples(1000), {1, 2, 3, 4}));
  EXPECT_EQ(policy->next_split(), first);
}

TEST(CdfBalancer, FirstFrameIsSplitOnItsOwnSamples) {
  const uint32_t positions = 3000;
  FramePreview first;
  first.samples = irregular_samples(positions);
  for (uint32_t i = 0; i < positions; ++i) first.samples[i] *= 1.0 + 3.0 * i / positions;
  double total = std::accumulate(first.samples.begin(), first.samples.end(), 0.0);
  for (SplitStrategy s : {SplitStrategy::Balanced, SplitStrategy::Cost, SplitStrategy::Current}) {
    auto policy = make_split_policy(s, 3, positions);
    EXPECT_EQ(policy->next_split(), equal_area_split(positions, 3)) << "nothing known: by area";
    Split split = policy->next_split(first);
    ASSERT_EQ(split_problem(split, positions), "");
    EXPECT_FALSE(split == equal_area_split(positions, 3));
    for (size_t i = 0; i < 3; ++i)
      EXPECT_NEAR(weight_of(first.samples, split[i]), total / 3, 10.0) << strategy_name(s);
  }
}

TEST(CdfBalancer, SharesFollowSpeedsAndTheCdf) {
  const uint32_t positions = 5000;
  std::vector<double> samples = irregular_samples(positions);
  double total = std::accumulate(samples.begin(), samples.end(), 0.0);
  std::vector<double> speeds{1.0, 1.0, 2.0, 4.0};  // samples per ns
  for (SplitStrategy s : {SplitStrategy::Balanced, SplitStrategy::Cost}) {
    auto policy = make_split_policy(s, 4, positions);
    policy->observe(frame_with_speeds(*policy, samples, speeds));
    Split split = policy->next_split();
    ASSERT_EQ(split_problem(split, positions), "");
    // t = N / sum(p) = total / 8; n_i = t * p_i.
    for (size_t i = 0; i < 4; ++i)
      EXPECT_NEAR(weight_of(samples, split[i]), total / 8 * speeds[i], 10.0)
          << strategy_name(s) << " device " << i;
    std::vector<double> estimated = policy->speeds();
    double factor = s == SplitStrategy::Cost ? 3.0 : 1.0;  // cost per ns
    for (size_t i = 0; i < 4; ++i) EXPECT_NEAR(estimated[i], speeds[i] * factor, 1e-9);
  }
}

TEST(CdfBalancer, CostWeightsFollowCostNotSampleCount) {
  // Same samples everywhere, but the right half costs 3x as much per sample.
  const uint32_t positions = 1000;
  auto policy = make_split_policy(SplitStrategy::Cost, 2, positions);
  FrameFeedback f;
  f.split = policy->next_split();
  f.samples.assign(positions, 1.0);
  f.cost.assign(positions, 1.0);
  for (uint32_t i = positions / 2; i < positions; ++i) f.cost[i] = 3.0;
  f.devices = {{500, 500, 500}, {500, 1500, 1500}};  // both do 1 cost unit per ns
  policy->observe(f);
  Split split = policy->next_split();
  // Total cost 2000: each device 1000, i.e. the boundary where the CDF reaches 1000 (at 667).
  EXPECT_NEAR(double(split[0].end), 666.7, 1.0);
  auto samples_policy = make_split_policy(SplitStrategy::Balanced, 2, positions);
  f.split = samples_policy->next_split();
  samples_policy->observe(f);
  // Counting samples, device 1 looks 3x slower (same samples, 3x the time): t = 1000 / (4/3).
  EXPECT_EQ(samples_policy->next_split()[0].end, 750u);
}

TEST(CdfBalancer, CurrentFollowsTheNextFramesRaysByType) {
  // Frame 1: camera rays everywhere, one GI ray per position on the left half. A GI ray costs
  // 10, a camera ray 1; positions 0..99 cost twice what their types predict.
  const uint32_t positions = 1000;
  const auto camera = size_t(RayType::Camera), gi = size_t(RayType::DiffuseGI);
  auto policy = make_split_policy(SplitStrategy::Current, 2, positions);
  FrameFeedback f;
  f.split = policy->next_split();
  f.samples.assign(positions, 1.0);
  f.rays.assign(positions, TypedRays{});
  f.cost.assign(positions, 0.0);
  for (uint32_t p = 0; p < positions; ++p) {
    f.rays[p][camera] = 1;
    f.rays[p][gi] = p < 500 ? 1 : 0;
    f.cost[p] = (p < 500 ? 11.0 : 1.0) * (p < 100 ? 2.0 : 1.0);
  }
  f.type_cost[camera] = 1;
  f.type_cost[gi] = 10;
  double left = std::accumulate(f.cost.begin(), f.cost.begin() + 500, 0.0);
  double right = std::accumulate(f.cost.begin() + 500, f.cost.end(), 0.0);
  f.devices = {{500, left, left}, {500, right, right}};  // 1 cost unit per ns each
  policy->observe(f);
  // Frame 2: the GI rays moved to the right half. Predicted cost: 2 on 0..99, 1 on 100..499,
  // 11 on 500..999; total 6100, so device 0's 3050 ends at 500 + (3050 - 600) / 11 = 722.7.
  FramePreview next{f.samples, f.rays};
  for (uint32_t p = 0; p < positions; ++p) next.rays[p][gi] = p < 500 ? 0 : 1;
  Split split = policy->next_split(next);
  EXPECT_EQ(split[0].end, 723u);
  // Without a preview, the previous frame's cost: 7100 in all, 3550 reached at 222.7.
  EXPECT_EQ(policy->next_split()[0].end, 223u);
}

TEST(CdfBalancer, DeviceWithZeroTimeKeepsItsLastSpeed) {
  const uint32_t positions = 4000;
  std::vector<double> samples(positions, 1.0);
  auto policy = make_split_policy(SplitStrategy::Balanced, 4, positions);
  policy->observe(frame_with_speeds(*policy, samples, {1, 1, 1, 3}));
  std::vector<double> before = policy->speeds();
  FrameFeedback f = frame_with_speeds(*policy, samples, {1, 1, 1, 3});
  f.devices[3].time_ns = 0;  // e.g. a device that reported nothing
  policy->observe(f);
  EXPECT_DOUBLE_EQ(policy->speeds()[3], before[3]);
  Split split = policy->next_split();
  EXPECT_EQ(split_problem(split, positions), "");
  EXPECT_NEAR(double(split[3].size()), positions * 0.5, 2.0);
}

TEST(CdfBalancer, DeviceNeverMeasuredGetsTheMeanSpeed) {
  const uint32_t positions = 3000;
  std::vector<double> samples(positions, 1.0);
  auto policy = make_split_policy(SplitStrategy::Balanced, 3, positions);
  FrameFeedback f = frame_with_speeds(*policy, samples, {1, 3, 1});
  f.devices[2].time_ns = 0;
  policy->observe(f);
  EXPECT_DOUBLE_EQ(policy->speeds()[2], 2.0) << "mean of 1 and 3";
  Split split = policy->next_split();
  EXPECT_EQ(split_problem(split, positions), "");
  EXPECT_NEAR(double(split[2].size()), positions * 2.0 / 6.0, 2.0);
  EXPECT_GT(split[2].size(), 0u) << "a device with no measurement is not starved";
}

TEST(CdfBalancer, EmptyFrameSplitsTheAreaBySpeed) {
  const uint32_t positions = 1200;
  auto policy = make_split_policy(SplitStrategy::Balanced, 2, positions);
  policy->observe(frame_with_speeds(*policy, std::vector<double>(positions, 1.0), {1, 2}));
  FrameFeedback empty;
  empty.split = policy->next_split();
  empty.samples.assign(positions, 0.0);
  empty.cost.assign(positions, 0.0);
  empty.devices = {{0, 0, 0}, {0, 0, 0}};
  policy->observe(empty);
  Split split = policy->next_split();
  EXPECT_EQ(split_problem(split, positions), "");
  EXPECT_EQ(split[0].size(), 400u) << "speeds survive an empty frame; area is split 1:2";
  EXPECT_NEAR(policy->speeds()[1], 2.0, 1e-12);
}

TEST(CdfBalancer, OneDeviceTakesTheWholeFrame) {
  auto policy = make_split_policy(SplitStrategy::Cost, 1, 77);
  EXPECT_EQ(policy->next_split(), (Split{{0, 77}}));
  policy->observe(frame_with_speeds(*policy, irregular_samples(77), {5}));
  EXPECT_EQ(policy->next_split(), (Split{{0, 77}}));
}

TEST(CdfBalancer, RejectsFeedbackForOtherDeviceCounts) {
  auto policy = make_split_policy(SplitStrategy::Balanced, 2, 10);
  FrameFeedback f;
  f.devices.resize(3);
  EXPECT_THROW(policy->observe(f), std::invalid_argument);
}

TEST(SplitStrategy, NamesRoundTrip) {
  for (const std::string& name : strategy_names())
    EXPECT_EQ(strategy_name(*strategy_from_name(name)), name);
  EXPECT_FALSE(strategy_from_name("afr"));
}

}  // namespace
}  // namespace rtsim::multi
