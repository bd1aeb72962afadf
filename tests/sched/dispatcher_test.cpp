// The ray dispatcher alone: delivery bandwidth, latency, and the bound on rays in flight.
#include <gtest/gtest.h>

#include "model/sched/dispatcher.h"

namespace rtsim {
namespace {

std::vector<Ray> some_rays(size_t n) {
  std::vector<Ray> rays(n);
  for (size_t i = 0; i < n; ++i) rays[i].pixel = uint32_t(i);
  return rays;
}

TEST(RayDispatcher, DeliversAtItsBandwidthAfterItsLatency) {
  std::vector<Ray> rays = some_rays(8);
  VectorRaySource source(rays);
  RayContextPool pool(8);
  RayDispatcher d({2.0, 5}, source, pool, nullptr);
  std::vector<RayContext*> out;
  ASSERT_EQ(d.take(0, 0, 4, out), 4u);
  // Slots at 0, 0.5, 1, 1.5: two rays in cycle 0, two in cycle 1, plus 5 cycles of latency.
  EXPECT_EQ(out[0]->ready, 5u);
  EXPECT_EQ(out[1]->ready, 5u);
  EXPECT_EQ(out[2]->ready, 6u);
  EXPECT_EQ(out[3]->ready, 6u);
  out.clear();
  ASSERT_EQ(d.take(1, 0, 2, out), 2u);
  EXPECT_EQ(out[0]->dispatched, 2u) << "the port is busy until cycle 2";
  EXPECT_EQ(d.stats().wait_cycles, 2u);
  EXPECT_EQ(out[0]->sequence, 4u) << "rays keep their stream order";
}

TEST(RayDispatcher, RaysInFlightAreBoundedByThePool) {
  std::vector<Ray> rays = some_rays(10);
  VectorRaySource source(rays);
  RayContextPool pool(3);
  RayDispatcher d({100.0, 0}, source, pool, nullptr);
  std::vector<RayContext*> out;
  EXPECT_EQ(d.take(0, 0, 5, out), 3u) << "only 3 contexts";
  EXPECT_EQ(d.stats().pool_empty, 1u);
  d.retire(*out[0], 10);
  EXPECT_EQ(d.in_flight(), 2u);
  std::vector<RayContext*> more;
  EXPECT_EQ(d.take(0, 10, 5, more), 1u) << "one context came back";
  EXPECT_FALSE(d.exhausted());
}

TEST(RayDispatcher, ExhaustedAtTheEndOfTheStream) {
  std::vector<Ray> rays = some_rays(2);
  VectorRaySource source(rays);
  RayContextPool pool(4);
  RayDispatcher d({1.0, 0}, source, pool, nullptr);
  std::vector<RayContext*> out;
  EXPECT_EQ(d.take(0, 0, 4, out), 2u);
  EXPECT_TRUE(d.exhausted());
  EXPECT_EQ(d.take(0, 0, 4, out), 0u);
}

}  // namespace
}  // namespace rtsim
