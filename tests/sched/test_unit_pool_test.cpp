// Ray-box / ray-triangle unit pools alone: exact latency, issue width, unit count, and
// back-pressure, including requests that arrive out of order.
#include <gtest/gtest.h>

#include "model/sched/test_unit_pool.h"

namespace rtsim {
namespace {

TEST(TestUnitPool, ExactLatencyEdge) {
  TestUnitPool pool({1, 8, 9});
  Cycle ready = pool.reserve(100, 8);
  EXPECT_NE(ready, 100u + 9 - 1) << "not ready at latency - 1";
  EXPECT_EQ(ready, 100u + 9) << "ready exactly at latency";
  EXPECT_EQ(pool.stats().issues, 1u);
  EXPECT_EQ(pool.stats().stall_cycles, 0u);
}

TEST(TestUnitPool, IssueWidthSplitsWideRequests) {
  TestUnitPool pool({1, 4, 10});
  EXPECT_EQ(pool.reserve(0, 4), 10u) << "4 boxes on a 4-wide unit: one issue";
  EXPECT_EQ(pool.reserve(50, 5), 50u + 1 + 10) << "5 boxes: two issues, ready after the second";
  EXPECT_EQ(pool.stats().issues, 3u);
  EXPECT_EQ(pool.reserve(80, 0), 90u) << "a step with no tests still passes the unit once";
}

TEST(TestUnitPool, PipelinedThroughputAndBackPressure) {
  TestUnitPool pool({1, 1, 12});
  // Three one-test requests in one cycle on one unit: one issue per cycle, pipelined.
  EXPECT_EQ(pool.reserve(5, 1), 17u);
  EXPECT_EQ(pool.reserve(5, 1), 18u);
  EXPECT_EQ(pool.reserve(5, 1), 19u);
  EXPECT_EQ(pool.stats().stall_cycles, 0u + 1 + 2) << "the later ones waited 1 and 2 cycles";
}

TEST(TestUnitPool, CountAddsParallelUnits) {
  TestUnitPool pool({2, 1, 6});
  EXPECT_EQ(pool.reserve(0, 1), 6u);
  EXPECT_EQ(pool.reserve(0, 1), 6u) << "the second unit takes the second request";
  EXPECT_EQ(pool.reserve(0, 1), 7u) << "the third waits a cycle";
  EXPECT_EQ(pool.reserve(0, 3), 8u) << "3 tests: 2 issues next cycle (one left), 1 after";
}

TEST(TestUnitPool, OutOfOrderArrivalsKeepTheirOwnCycles) {
  TestUnitPool pool({1, 1, 4});
  EXPECT_EQ(pool.reserve(300, 1), 304u) << "data arriving later reserves first";
  EXPECT_EQ(pool.reserve(100, 1), 104u) << "an earlier arrival is not delayed by it";
  EXPECT_EQ(pool.reserve(300, 1), 305u) << "the same cycle again is busy";
  EXPECT_EQ(pool.stats().calendar_conflicts, 0u);
}

TEST(TestUnitPool, NeverExceedsIssueCapacity) {
  // 2 units x 3 tests per issue: a long busy stretch may use at most 2 issues per cycle.
  TestUnitPool pool({2, 3, 5});
  uint64_t seed = 7;
  Cycle last_ready = 0;
  for (int i = 0; i < 2000; ++i) {
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    Cycle arrival = 1000 + (seed >> 33) % 200;
    last_ready = std::max(last_ready, pool.reserve(arrival, uint32_t(1 + (seed >> 20) % 8)));
  }
  double cycles_used = double(last_ready - 5 - 1000 + 1);
  EXPECT_GE(cycles_used * 2, double(pool.stats().issues)) << "issues per cycle <= unit count";
}

TEST(TestUnitPool, RejectsImpossibleConfigs) {
  EXPECT_THROW(TestUnitPool({0, 1, 1}), std::invalid_argument);
  EXPECT_THROW(TestUnitPool({1, 0, 1}), std::invalid_argument);
  EXPECT_THROW(TestUnitPool({1, 1, 0}), std::invalid_argument);
}

}  // namespace
}  // namespace rtsim
