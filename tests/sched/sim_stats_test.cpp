// What the stats collector makes of retired rays: a warp's latency is its slowest ray's, from
// the first dispatch of its rays to the last retirement, whatever order they finish in.
#include <gtest/gtest.h>

#include "model/sched/sim_stats.h"

namespace rtsim {
namespace {

RayContext ray_at(uint64_t sequence, Cycle dispatched, RayType type = RayType::Shadow) {
  RayContext r;
  r.sequence = sequence;
  r.dispatched = dispatched;
  r.ray.type = type;
  return r;
}

TEST(SimStats, AWarpWaitsFromItsFirstDispatchToItsLastRetirement) {
  SimStatsCollector stats(0, 0, 4);
  // Warp 0: rays 0..3 dispatched at 10..13, retiring out of order; the last at 500.
  stats.retired(ray_at(2, 12), 100);
  stats.retired(ray_at(0, 10), 500);
  stats.retired(ray_at(3, 13), 50);
  const LatencyHistogram& warps = stats.by_type()[size_t(RayType::Shadow)].warp_latency;
  EXPECT_EQ(warps.count(), 0u) << "a warp counts once all its rays are back";
  stats.retired(ray_at(1, 11), 200);
  EXPECT_EQ(warps.count(), 1u);
  EXPECT_EQ(warps.max(), 490u) << "500 - 10";
  const LatencyHistogram& rays = stats.by_type()[size_t(RayType::Shadow)].latency;
  EXPECT_EQ(rays.count(), 4u);
  EXPECT_EQ(rays.max(), 490u);
  EXPECT_EQ(rays.sum(), 88u + 490 + 37 + 189);
}

TEST(SimStats, TheLastShortWarpCountsAtTheEndForItsFirstRaysType) {
  SimStatsCollector stats(0, 0, 4);
  stats.retired(ray_at(5, 30, RayType::Camera), 90);
  stats.retired(ray_at(4, 20, RayType::DiffuseGI), 60);
  stats.retired(ray_at(6, 25, RayType::Camera), 300);
  const auto& by_type = stats.by_type();
  EXPECT_EQ(by_type[size_t(RayType::DiffuseGI)].warp_latency.count(), 0u);
  stats.finish();
  EXPECT_EQ(by_type[size_t(RayType::DiffuseGI)].warp_latency.count(), 1u) << "ray 4 leads";
  EXPECT_EQ(by_type[size_t(RayType::DiffuseGI)].warp_latency.max(), 280u) << "300 - 20";
  EXPECT_EQ(by_type[size_t(RayType::Camera)].warp_latency.count(), 0u);
}

TEST(SimStats, WarmUpRaysCountNoWarp) {
  SimStatsCollector stats(0, 0, 2);
  stats.measure_from(2, 0);
  stats.retired(ray_at(0, 0), 10);
  stats.retired(ray_at(1, 0), 10);
  stats.retired(ray_at(2, 5), 40);
  stats.retired(ray_at(3, 6), 30);
  stats.finish();
  const LatencyHistogram& warps = stats.by_type()[size_t(RayType::Shadow)].warp_latency;
  EXPECT_EQ(warps.count(), 1u);
  EXPECT_EQ(warps.max(), 35u);
}

}  // namespace
}  // namespace rtsim
