// The cache's lookup side with a mock memory below it: banks and their ports, the data port's
// bandwidth, sectored lines, and the MSHR merge limit; cycle-exact.
#include <gtest/gtest.h>

#include "mock_memory.h"
#include "model/mem/cache.h"

namespace rtsim {
namespace {

CacheConfig banked_cache() {
  CacheConfig c;
  c.size_bytes = 1024;
  c.line_bytes = 64;
  c.ways = 2;
  c.hit_latency = 4;
  c.mshrs = 4;
  c.banks = 2;
  c.bank_ports = 1;
  return c;
}

TEST(CacheBanks, TwoLookupsOfOneBankInACycleTakeOneMoreCycleThanOfTwoBanks) {
  test::MockMemory mem(100);
  Cache cache(banked_cache(), &mem);
  for (uint64_t addr : {0x000, 0x040, 0x080}) cache.read(addr, 64, 1000 * (addr / 0x40));
  EXPECT_EQ(cache.read(0x000, 64, 5000), 5004u) << "bank 0";
  EXPECT_EQ(cache.read(0x040, 64, 5000), 5004u) << "bank 1, the same cycle";
  EXPECT_EQ(cache.stats().bank_conflicts, 0u);
  EXPECT_EQ(cache.read(0x000, 64, 6000), 6004u) << "bank 0";
  EXPECT_EQ(cache.read(0x080, 64, 6000), 6005u) << "bank 0 again: its port is taken";
  EXPECT_EQ(cache.stats().bank_conflicts, 1u);
  EXPECT_EQ(cache.stats().bank_stall_cycles, 1u);
  EXPECT_EQ(cache.read(0x080, 64, 6002), 6006u) << "a later cycle finds the port free";
}

TEST(CacheBanks, EachBankStartsItsPortsWorthOfLookupsACycle) {
  test::MockMemory mem(100);
  CacheConfig c = banked_cache();
  c.bank_ports = 2;
  Cache cache(c, &mem);
  for (uint64_t addr : {0x000, 0x080, 0x100}) cache.read(addr, 64, 1000 * (addr / 0x80));
  EXPECT_EQ(cache.read(0x000, 64, 5000), 5004u);
  EXPECT_EQ(cache.read(0x080, 64, 5000), 5004u) << "the bank's second port";
  EXPECT_EQ(cache.read(0x100, 64, 5000), 5005u) << "a third waits a cycle";
}

TEST(CachePort, NLinesThroughThePortTakeNTimesLineOverBandwidth) {
  test::MockMemory mem(100);
  CacheConfig c = banked_cache();
  c.bank_ports = 0;
  c.bytes_per_cycle = 16;  // a 64-byte line takes 4 cycles
  Cache cache(c, &mem);
  for (uint64_t line = 0; line < 4; ++line) cache.read(line * 64, 64, line * 1000);
  for (uint64_t line = 0; line < 4; ++line)
    EXPECT_EQ(cache.read(line * 64, 64, 9000), 9004u + 4 * line) << "line " << line;
  EXPECT_EQ(cache.stats().port_stall_cycles, 4u + 8 + 12);
  EXPECT_EQ(cache.read(0, 64, 9016), 9020u) << "the port is free again after 4 x 64 / 16 cycles";
  EXPECT_EQ(cache.read(0, 16, 9030), 9034u);
  EXPECT_EQ(cache.read(0, 16, 9030), 9035u) << "16 bytes take one cycle";
}

TEST(CacheSectors, AMissFetchesOnlyTheSectorsItNeeds) {
  test::MockMemory mem(100);
  CacheConfig c = banked_cache();
  c.line_bytes = 128;
  c.sector_bytes = 32;
  Cache cache(c, &mem);
  EXPECT_EQ(cache.block_bytes(), 32u);
  EXPECT_EQ(cache.read(0x1000, 16, 0), 104u);
  EXPECT_EQ(cache.read(0x1020, 32, 200), 304u) << "another sector of the line: its own miss";
  ASSERT_EQ(mem.requests.size(), 2u);
  EXPECT_EQ(mem.requests[1].addr, 0x1020u);
  EXPECT_EQ(mem.requests[1].bytes, 32u);
  EXPECT_EQ(cache.read(0x1000, 64, 400), 404u) << "both sectors present: a hit";
  EXPECT_EQ(cache.read(0x1030, 48, 500), 604u) << "sector 1 hits, sector 2 misses";
  EXPECT_EQ(cache.stats().misses, 3u);
  EXPECT_EQ(cache.stats().bytes_below, 96u);
  EXPECT_EQ(cache.stats().accesses, 6u) << "one access per sector";
}

TEST(CacheMerges, PastTheMergeLimitARequestReplaysAfterTheData) {
  test::MockMemory mem(100);
  CacheConfig c = banked_cache();
  c.bank_ports = 0;
  c.merge_limit = 1;
  Cache cache(c, &mem);
  EXPECT_EQ(cache.read(0x1000, 64, 0), 104u);
  EXPECT_EQ(cache.read(0x1000, 64, 10), 104u) << "merged";
  EXPECT_EQ(cache.read(0x1000, 64, 20), 108u) << "past the limit: a second lookup after the data";
  EXPECT_EQ(cache.stats().mshr_merges, 2u);
  EXPECT_EQ(cache.stats().merge_limit_stalls, 1u);
  EXPECT_EQ(cache.read(0x1000, 64, 200), 204u) << "filled: a plain hit";
}

TEST(CacheMerges, ReplaysAlsoWaitForDataReportedLater) {
  test::MockMemory mem(100, /*deferred=*/true);
  CacheConfig c = banked_cache();
  c.bank_ports = 0;
  c.merge_limit = 1;
  Cache cache(c, &mem);
  test::RecordingClient client;
  ReadCharge charge;
  for (uint64_t token = 0; token < 3; ++token)
    EXPECT_EQ(cache.read(0x1000, 64, 10 * token, &client, token, charge), kPending);
  mem.answer(0, 150);
  ASSERT_EQ(client.done.size(), 3u);
  EXPECT_EQ(client.done[0].ready, 150u);
  EXPECT_EQ(client.done[1].ready, 150u);
  EXPECT_EQ(client.done[2].ready, 154u);
}

}  // namespace
}  // namespace rtsim
