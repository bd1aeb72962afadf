// The banked DRAM at the edges of its timing, as Ramulator's tests are: latencies of a row
// hit, a closed bank and a row conflict; tFAW, tWTR and refresh holding commands back;
// bandwidth of streaming and of random closed-row reads against what the timing predicts.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "model/mem/dram_controller.h"

namespace rtsim {
namespace {

// One channel, one rank, 4 x 4 banks, 32-byte bursts of 2 clocks; DRAM and core clocks equal
// (1 GHz), so DRAM clocks are core cycles. Fields: row:rank:bankgroup:bank:column:channel.
BankedDramConfig small_config() {
  BankedDramConfig c;
  c.clock_mhz = 1000;
  c.channels = 1;
  c.mapping = "row:rank:bankgroup:bank:column:channel";
  c.refresh = DramRefresh::None;
  c.controller_latency = 0;
  c.timing.tCL = 20;
  c.timing.tCWL = 8;
  c.timing.tRCD_RD = 15;
  c.timing.tRCD_WR = 10;
  c.timing.tRP = 12;
  c.timing.tRAS = 30;
  c.timing.tRC = 42;
  c.timing.tCCD_S = 2;
  c.timing.tCCD_L = 4;
  c.timing.tRRD_S = 2;
  c.timing.tRRD_L = 4;
  c.timing.tFAW = 20;
  c.timing.tWTR_S = 3;
  c.timing.tWTR_L = 6;
  c.timing.tWR = 12;
  c.timing.tRTP = 4;
  c.timing.tRTW = 16;
  return c;
}

uint64_t address(const BankedDramConfig& c, uint32_t row, uint32_t group, uint32_t bank,
                 uint32_t column = 0) {
  uint64_t columns = c.row_bytes / c.burst_bytes();
  return (((uint64_t(row) * c.bank_groups + group) * c.banks_per_group + bank) * columns + column) *
         c.burst_bytes();
}

// Runs the controller until every read is done; returns the ready cycles by id.
std::vector<Cycle> run(DramController& dram, size_t reads) {
  std::vector<DramReadDone> done;
  for (Cycle next = dram.next_event(); next != kPending; next = dram.next_event())
    dram.advance(next, done);
  std::vector<Cycle> ready(reads, kPending);
  for (const DramReadDone& d : done) ready.at(d.id) = d.ready;
  return ready;
}

Cycle read_alone(DramController& dram, uint64_t id, uint64_t addr, Cycle at) {
  dram.enqueue(id, addr, 32, false, at);
  return run(dram, id + 1)[id];
}

// DRAM clocks to core cycles, rounded up, for a ratio that is not a whole number (1.75 GHz
// DRAM, 1.5 GHz core) and for clocks whose product with it needs more than 64 bits.
TEST(DramTiming, ClockConversionIsExactAtEveryMagnitude) {
  BankedDramConfig c = small_config();
  c.clock_mhz = 1750;
  DramController dram(c, 1.5);
  for (DramClock clock : {DramClock(0), DramClock(1), DramClock(7), DramClock(1'000'003),
                          DramClock(1) << 40, (DramClock(1) << 62) + 5, ~DramClock(0) / 2}) {
    auto exact = (unsigned __int128)clock * 1'500'000 + 1'750'000 - 1;
    EXPECT_EQ(dram.to_core(clock), Cycle(exact / 1'750'000)) << clock;
  }
}

TEST(DramTiming, ClosedBankRowHitAndRowConflictLatencies) {
  BankedDramConfig c = small_config();
  const DramTiming& t = c.timing;
  DramController dram(c, 1.0);
  uint32_t burst = c.burst_clocks();
  EXPECT_EQ(read_alone(dram, 0, address(c, 7, 1, 2), 100), 100 + t.tRCD_RD + t.tCL + burst)
      << "closed bank: ACT, then RD after tRCD";
  EXPECT_EQ(read_alone(dram, 1, address(c, 7, 1, 2, 5), 1000), 1000 + t.tCL + burst)
      << "open row: RD at once";
  EXPECT_EQ(read_alone(dram, 2, address(c, 9, 1, 2), 2000),
            2000 + t.tRP + t.tRCD_RD + t.tCL + burst)
      << "row conflict: PRE, ACT after tRP, RD after tRCD";
  EXPECT_EQ(dram.stats().row_misses, 1u);
  EXPECT_EQ(dram.stats().row_hits, 1u);
  EXPECT_EQ(dram.stats().row_conflicts, 1u);
  EXPECT_EQ(dram.stats().commands.act, 2u);
  EXPECT_EQ(dram.stats().commands.pre, 1u);
  EXPECT_EQ(dram.stats().commands.rd, 3u);
}

TEST(DramTiming, ClosedPagePolicyPrechargesAfterTheAccess) {
  BankedDramConfig c = small_config();
  c.page_policy = DramPagePolicy::Closed;
  c.read_queue = 128;  // enough requests to find a free bank: the device's limits, not the queue's
  const DramTiming& t = c.timing;
  DramController dram(c, 1.0);
  read_alone(dram, 0, address(c, 7, 0, 0), 0);
  EXPECT_EQ(read_alone(dram, 1, address(c, 7, 0, 0), 1000), 1000 + t.tRCD_RD + t.tCL + 2)
      << "the row was closed: the same row again is a closed-bank access";
  EXPECT_EQ(dram.stats().row_misses, 2u);
  EXPECT_EQ(dram.stats().commands.pre, 2u);
}

TEST(DramTiming, FifthActivateWaitsForTheFourActivateWindow) {
  BankedDramConfig c = small_config();
  DramChannel channel(c);
  for (uint32_t i = 0; i < 4; ++i) {
    DramAddress a{0, 0, i, 0, 1, 0};  // four bank groups: tRRD_S apart
    DramClock at = channel.earliest(DramCommand::Act, a, 0);
    EXPECT_EQ(at, i * c.timing.tRRD_S);
    channel.issue(DramCommand::Act, a, at);
  }
  DramAddress fifth{0, 0, 0, 1, 1, 0};
  EXPECT_EQ(channel.earliest(DramCommand::Act, fifth, 7), c.timing.tFAW)
      << "tRRD alone would allow it at " << 3 * c.timing.tRRD_S + c.timing.tRRD_L;
}

TEST(DramTiming, ReadAfterWriteWaitsForWriteToReadTurnaround) {
  BankedDramConfig c = small_config();
  const DramTiming& t = c.timing;
  DramChannel channel(c);
  DramAddress a{0, 0, 0, 0, 3, 0}, same_group{0, 0, 0, 1, 3, 0}, other_group{0, 0, 1, 0, 3, 0};
  for (const DramAddress& x : {a, same_group, other_group})
    channel.issue(DramCommand::Act, x, channel.earliest(DramCommand::Act, x, 0));
  DramClock wr = channel.earliest(DramCommand::Wr, a, 100);
  EXPECT_EQ(wr, 100u);
  DramClock data_end = channel.issue(DramCommand::Wr, a, wr);
  EXPECT_EQ(data_end, wr + t.tCWL + c.burst_clocks());
  EXPECT_EQ(channel.earliest(DramCommand::Rd, same_group, wr), data_end + t.tWTR_L);
  EXPECT_EQ(channel.earliest(DramCommand::Rd, other_group, wr), data_end + t.tWTR_S);
  EXPECT_EQ(channel.earliest(DramCommand::Pre, a, wr), data_end + t.tWR);
  DramClock rd = channel.earliest(DramCommand::Rd, a, 200);
  channel.issue(DramCommand::Rd, a, rd);
  EXPECT_EQ(channel.earliest(DramCommand::Wr, a, rd), rd + t.tRTW) << "read to write turnaround";
}

TEST(DramTiming, RefreshBlocksTheRankForTrfcEveryTrefi) {
  BankedDramConfig c = small_config();
  c.refresh = DramRefresh::AllBank;
  c.timing.tREFI = 1000;
  c.timing.tRFC = 100;
  const DramTiming& t = c.timing;
  DramController dram(c, 1.0);
  uint32_t closed = t.tRCD_RD + t.tCL + 2;
  EXPECT_EQ(read_alone(dram, 0, address(c, 1, 0, 0), 500), 500 + closed);
  // The refresh due at 1000 is issued at 1000 (after a PRE of the open row, tRP later) even
  // though the channel slept; a read arriving during it waits for tRFC.
  EXPECT_EQ(read_alone(dram, 1, address(c, 2, 1, 1), 1050), 1000 + t.tRP + t.tRFC + closed);
  EXPECT_EQ(read_alone(dram, 2, address(c, 3, 2, 2), 1500), 1500 + closed) << "refresh over";
  EXPECT_EQ(read_alone(dram, 3, address(c, 4, 3, 3), 3000), 3000 + t.tRFC + closed)
      << "the refresh due at 2000 is long over; the one at 3000 comes first";
  EXPECT_EQ(dram.stats().commands.ref, 3u);
  EXPECT_EQ(dram.stats().commands.pre, 3u) << "a refresh closes the open rows first: one at "
                                              "1000, two at 2000, none at 3000";
}

// The default config (GDDR6-like: 8 x16 channels, per-bank refresh) at a 1.5 GHz core.
BankedDramConfig gddr6_like() {
  BankedDramConfig c;
  c.refresh = DramRefresh::PerBank;
  c.timing.tREFIpb = c.timing.tREFI / c.banks();
  return c;
}

// Bytes per DRAM clock from the first arrival (cycle 0) to the last read's data.
double achieved_bytes_per_clock(DramController& dram, size_t reads, uint64_t bytes) {
  std::vector<Cycle> ready = run(dram, reads);
  Cycle last = *std::max_element(ready.begin(), ready.end()) - dram.config().controller_latency;
  return double(bytes) / (double(last) * dram.config().clock_mhz / 1500.0);
}

TEST(DramBandwidth, StreamingReadsReachNinetyPercentOfPeak) {
  BankedDramConfig c = gddr6_like();
  DramController dram(c, 1.5);
  const uint32_t kReads = 16384;  // 1 MiB of 64-byte lines
  for (uint32_t i = 0; i < kReads; ++i) dram.enqueue(i, uint64_t(i) * 64, 64, false, 0);
  double peak = double(c.channels) * c.burst_bytes() / c.burst_clocks();
  double achieved = achieved_bytes_per_clock(dram, kReads, uint64_t(kReads) * 64);
  EXPECT_GE(achieved, 0.9 * peak) << achieved << " of " << peak << " bytes per clock";
  EXPECT_GT(dram.stats().row_hits, 0.95 * double(dram.stats().commands.rd));
}

// Random rows, closed page: every 64-byte read (two bursts of one row) takes an ACT. A rank
// takes at most min(banks / tRC, 4 / tFAW, 1 / tRRD_S) ACTs per clock: the bound below, less
// what refresh takes.
TEST(DramBandwidth, RandomClosedRowReadsReachTheActivateBound) {
  BankedDramConfig c = gddr6_like();
  c.page_policy = DramPagePolicy::Closed;
  c.read_queue = 128;  // enough requests to find a free bank: the device's limits, not the queue's
  const DramTiming& t = c.timing;
  DramController dram(c, 1.5);
  const uint32_t kReads = 8000;
  uint64_t state = 7;
  for (uint32_t i = 0; i < kReads; ++i) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    dram.enqueue(i, (state >> 20) & ~uint64_t(63), 64, false, 0);
  }
  double acts_per_clock = std::min({double(c.banks()) / t.tRC, 4.0 / t.tFAW, 1.0 / t.tRRD_S});
  double bound = c.channels * c.ranks * acts_per_clock * 64;
  double achieved = achieved_bytes_per_clock(dram, kReads, uint64_t(kReads) * 64);
  EXPECT_LE(achieved, bound * 1.001);
  EXPECT_GE(achieved, 0.85 * bound) << achieved << " of a bound of " << bound << " bytes per clock";
  EXPECT_LE(dram.stats().commands.act, kReads) << "one ACT per read, fewer where two share a row";
  EXPECT_GE(dram.stats().commands.act, kReads * 99 / 100);
}

TEST(DramBandwidth, SameInputsGiveTheSameSchedule) {
  auto schedule = [] {
    BankedDramConfig c = gddr6_like();
    DramController dram(c, 1.5);
    uint64_t state = 3;
    for (uint32_t i = 0; i < 5000; ++i) {
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      dram.enqueue(i, (state >> 24) & ~uint64_t(63), 64, (state >> 62) == 0, i / 4);
    }
    return run(dram, 5000);
  };
  EXPECT_EQ(schedule(), schedule());
}

// A request joins its queue at its arrival, so a controller advanced late, with requests enqueued
// long before their cycles (as a DRAM module that wakes seldom sees them), takes the decisions
// of one advanced before each request: reads, writes, both page policies, per-bank refresh.
TEST(DramBandwidth, AdvancingLateChangesNoDecision) {
  for (DramPagePolicy policy : {DramPagePolicy::Open, DramPagePolicy::Closed}) {
    BankedDramConfig c = gddr6_like();
    c.page_policy = policy;
    DramController eager(c, 1.5), late(c, 1.5);
    std::vector<DramReadDone> eager_done, late_done;
    uint64_t state = 11;
    Cycle at = 0;
    for (uint32_t i = 0; i < 20000; ++i) {
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      at += (i / 2000 % 2) * ((state >> 60) % 5);  // floods that fill the queues, and gaps
      if ((state >> 40) % 500 == 0) at += 3000;
      uint64_t addr = (state >> 22) & ~uint64_t(63);
      bool write = (state >> 61) == 0;
      if (at > 0) eager.advance(at - 1, eager_done);
      eager.enqueue(i, addr, 64, write, at);
      late.enqueue(i, addr, 64, write, at);
      if (i % 1000 == 999) late.advance(at - 200, late_done);
    }
    for (DramController* dram : {&eager, &late}) {
      std::vector<DramReadDone>& done = dram == &eager ? eager_done : late_done;
      for (Cycle next = dram->next_event(); next != kPending; next = dram->next_event())
        dram->advance(next, done);
    }
    ASSERT_EQ(eager_done.size(), late_done.size()) << int(policy);
    for (size_t i = 0; i < eager_done.size(); ++i) {
      EXPECT_EQ(eager_done[i].id, late_done[i].id) << i;
      EXPECT_EQ(eager_done[i].ready, late_done[i].ready) << i;
    }
    const BankedDramStats &e = eager.stats(), &l = late.stats();
    EXPECT_EQ(e.row_hits, l.row_hits);
    EXPECT_EQ(e.row_conflicts, l.row_conflicts);
    EXPECT_EQ(e.commands.ref_pb, l.commands.ref_pb);
    EXPECT_EQ(e.refresh_stall_clocks, l.refresh_stall_clocks);
    EXPECT_EQ(e.queued_burst_clocks, l.queued_burst_clocks);
  }
}

}  // namespace
}  // namespace rtsim
