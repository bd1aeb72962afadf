// Latency percentiles in constant memory: exact below 1024 cycles, within 1.6% above.
#include <gtest/gtest.h>

#include "model/mem/latency_histogram.h"
#include "model/sched/stats_registry.h"

namespace rtsim {
namespace {

TEST(LatencyHistogram, ExactPercentilesForSmallValues) {
  LatencyHistogram h;
  for (uint64_t v = 1; v <= 100; ++v) h.add(v);
  EXPECT_EQ(h.percentile(0.50), 50u);
  EXPECT_EQ(h.percentile(0.95), 95u);
  EXPECT_EQ(h.percentile(0.99), 99u);
  EXPECT_EQ(h.max(), 100u);
  EXPECT_DOUBLE_EQ(h.mean(), 50.5);
}

TEST(LatencyHistogram, BoundedErrorForLargeValues) {
  LatencyHistogram h;
  for (uint64_t v = 1; v <= 100000; ++v) h.add(v * 37);
  for (double p : {0.5, 0.95, 0.99}) {
    double exact = p * 100000 * 37;
    EXPECT_NEAR(double(h.percentile(p)), exact, exact * 0.016) << "p" << p;
  }
  EXPECT_EQ(h.percentile(1.0), 3700000u) << "never above the largest value";
}

TEST(StatsRegistry, RatiosAreDerivedWhenWritten) {
  StatsRegistry r;
  r.counter("rt0.l1.hits", 30);
  r.counter("rt0.l1.accesses", 40);
  r.ratio("rt0.l1.hit_rate", "rt0.l1.hits", "rt0.l1.accesses");
  r.ratio("empty", "rt0.l1.hits", "missing");
  nlohmann::ordered_json j = r.to_json();
  EXPECT_EQ(j["counters"]["rt0.l1.hits"], 30);
  EXPECT_DOUBLE_EQ(j["derived"]["rt0.l1.hit_rate"].get<double>(), 0.75);
  EXPECT_DOUBLE_EQ(j["derived"]["empty"].get<double>(), 0.0) << "a zero denominator gives 0";
  EXPECT_THROW(r.counter("rt0.l1.hits", 1), std::logic_error) << "one name, one counter";
}

TEST(StatsRegistry, SubtractLeavesWhatAccruedSinceASnapshotAndKeepsGauges) {
  auto report = [](uint64_t hits, uint64_t accesses, uint64_t peak, bool port) {
    StatsRegistry r;
    r.counter("cycles", accesses * 2);
    r.counter("l2.hits", hits);
    r.counter("l2.accesses", accesses);
    r.real("dram.busy_cycles", double(hits) / 2);
    r.gauge("treelet_queues.max_queued", peak);
    if (port) r.counter("xbar.rt7.up.bytes", 64);  // created after the snapshot
    r.ratio("l2.hit_rate", "l2.hits", "l2.accesses");
    return r;
  };
  StatsRegistry warm = report(10, 40, 500, false);
  StatsRegistry end = report(70, 100, 900, true);
  end.subtract(warm);
  EXPECT_EQ(end.value("cycles"), 120.0);
  EXPECT_EQ(end.value("l2.hits"), 60.0);
  EXPECT_DOUBLE_EQ(end.value("l2.hit_rate"), 1.0) << "60 of 60 since the snapshot";
  EXPECT_DOUBLE_EQ(end.value("dram.busy_cycles"), 30.0);
  EXPECT_EQ(end.value("treelet_queues.max_queued"), 900.0) << "a level, not an accumulation";
  EXPECT_EQ(end.value("xbar.rt7.up.bytes"), 64.0) << "absent from the snapshot: from 0";
  EXPECT_EQ(end.to_json()["counters"]["treelet_queues.max_queued"], 900);
}

}  // namespace
}  // namespace rtsim
