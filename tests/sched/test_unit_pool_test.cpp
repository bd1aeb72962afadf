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

TEST(TestUnitPool, SharedSlotsTakeEitherKindOneIssueACycle) {
  // AMD RDNA2's ray accelerator: 4 box tests or 1 triangle test a clock, one issue shared.
  TestUnitPool box({1, 4, 8}), triangle({1, 1, 12});
  EXPECT_EQ(box.reserve(0, 8), 1u + 8) << "8 boxes: issues at cycles 0 and 1";
  EXPECT_EQ(box.reserve_as(triangle, 0, 1), 2u + 12) << "the triangle waits for cycle 2";
  EXPECT_EQ(box.reserve(0, 4), 3u + 8) << "and the next box issue for cycle 3";
  EXPECT_EQ(box.reserve_as(triangle, 0, 2), 5u + 12) << "2 triangles: cycles 4 and 5";
  EXPECT_EQ(triangle.reserve(0, 1), 12u) << "the triangle pool's own slots stay free";
  EXPECT_EQ(box.stats().issues, 3u);
  EXPECT_EQ(triangle.stats().issues, 1u + 2 + 1) << "each kind counts its own issues";
  EXPECT_EQ(triangle.stats().tests, 1u + 2 + 1);
  EXPECT_EQ(triangle.stats().stall_cycles, 2u + 4) << "waits in the shared slots";
}

TEST(TestUnitPool, TestsACycleAreCountTimesWidth) {
  // Intel Xe-HPG: 2 traversal pipelines a 6-wide node a clock each = 12 box tests a clock.
  TestUnitPool pool({2, 6, 8});
  Cycle last = 0;
  for (int i = 0; i < 600; ++i) last = std::max(last, pool.reserve(0, 6));
  EXPECT_EQ(last, 299u + 8) << "600 nodes of 6 boxes: 3600 tests in 300 cycles";
  EXPECT_DOUBLE_EQ(double(pool.stats().tests) / (last - 8 + 1), 12.0);
}

TEST(TestUnitPool, RejectsImpossibleConfigs) {
  EXPECT_THROW(TestUnitPool({0, 1, 1}), std::invalid_argument);
  EXPECT_THROW(TestUnitPool({1, 0, 1}), std::invalid_argument);
  EXPECT_THROW(TestUnitPool({1, 1, 0}), std::invalid_argument);
}

}  // namespace
}  // namespace rtsim
