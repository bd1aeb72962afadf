// DRAM alone: exact latency, bandwidth never exceeded, queue back-pressure.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "model/mem/dram.h"

namespace rtsim {
namespace {

DramConfig config(double bpc, uint32_t latency, uint32_t depth) {
  DramConfig c;
  c.bytes_per_cycle = bpc;
  c.latency = latency;
  c.queue_depth = depth;
  return c;
}

TEST(Dram, LoneRequestIsReadyAfterTransferPlusLatency) {
  Dram dram(config(16, 100, 8));
  Cycle ready = dram.read(0, 64, 10);
  EXPECT_EQ(ready, 10u + 4 + 100);
  EXPECT_EQ(dram.stats().bytes, 64u);
}

TEST(Dram, BackToBackRequestsShareTheBusAtPeakBandwidth) {
  Dram dram(config(16, 100, 1000));
  for (int k = 0; k < 50; ++k)
    EXPECT_EQ(dram.read(uint64_t(k) * 64, 64, 0), Cycle(4 * (k + 1) + 100));
  EXPECT_DOUBLE_EQ(dram.stats().busy_cycles, 200.0);
}

TEST(Dram, BandwidthIsNeverExceededOnRandomArrivals) {
  Dram dram(config(8, 50, 16));
  uint64_t state = 42;
  Cycle now = 0;
  std::vector<std::pair<Cycle, uint32_t>> done;  // (ready, bytes)
  for (int i = 0; i < 20000; ++i) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    now += (state >> 60) % 3;  // bursts: several requests in the same cycle
    uint32_t bytes = 32u << ((state >> 40) % 3);
    done.push_back({dram.read(state, bytes, now), bytes});
  }
  std::sort(done.begin(), done.end());
  // Data ready by cycle T left the bus by T - latency: at most 8 bytes per cycle since cycle 0.
  uint64_t delivered = 0;
  for (const auto& [ready, bytes] : done) {
    delivered += bytes;
    ASSERT_LE(double(delivered), 8.0 * double(ready - 50))
        << "bandwidth exceeded by cycle " << ready;
  }
  EXPECT_GT(dram.stats().queue_stall_cycles, 0u) << "the stream should fill the queue";
}

TEST(Dram, FullQueueDelaysArrivals) {
  Dram dram(config(1, 0, 2));  // 64-cycle transfers, 2 may wait
  dram.read(0, 64, 0);         // on the bus 0..64
  dram.read(0, 64, 0);         // waits, starts 64
  dram.read(0, 64, 0);         // waits, starts 128
  EXPECT_EQ(dram.stats().queue_stall_cycles, 0u);
  EXPECT_EQ(dram.read(0, 64, 0), 256u) << "fourth request waits for a queue slot, then the bus";
  EXPECT_EQ(dram.stats().queue_stall_cycles, 64u);
}

TEST(Dram, TransfersMoveWholeBursts) {
  DramConfig c{32.0, 100, 8};
  c.burst_bytes = 32;
  Dram dram(c);
  dram.write(0x1004, 8, 0);
  EXPECT_EQ(dram.stats().write_bytes, 32u);
  dram.write(0x101c, 40, 10);  // 0x101c..0x1043 touches the bursts at 0x1000, 0x1020, 0x1040
  EXPECT_EQ(dram.stats().write_bytes, 32u + 96);
  EXPECT_EQ(dram.read(0x2000, 64, 1000), 1000u + 2 + 100) << "aligned lines are whole bursts";
  EXPECT_EQ(dram.stats().bytes, 32u + 96 + 64);
}

TEST(Dram, RejectsImpossibleConfigs) {
  EXPECT_EQ(dram_config_problem(config(0, 10, 4)), "bytes_per_cycle must be positive");
  EXPECT_EQ(dram_config_problem(config(4, 10, 0)), "queue_depth must be at least 1");
  EXPECT_THROW(Dram(config(-1, 10, 4)), std::invalid_argument);
}

}  // namespace
}  // namespace rtsim
