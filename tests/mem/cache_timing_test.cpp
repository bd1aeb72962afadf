// The cache alone with a mock memory below it: exact hit and miss latencies, miss merging,
// MSHR back-pressure, and a level below that reports its data later.
#include <gtest/gtest.h>

#include "mock_memory.h"
#include "model/mem/cache.h"

namespace rtsim {
namespace {

CacheConfig small_cache() {
  CacheConfig c;
  c.size_bytes = 1024;
  c.line_bytes = 64;
  c.ways = 2;
  c.hit_latency = 4;
  c.mshrs = 2;
  return c;
}

TEST(CacheTiming, HitIsReadyExactlyAtHitLatency) {
  test::MockMemory mem(100);
  Cache cache(small_cache(), &mem);
  cache.read(0x1000, 64, 0);
  Cycle ready = cache.read(0x1000, 64, 500);
  EXPECT_GT(ready, 500u + 4 - 1) << "a hit must not be ready at hit_latency - 1";
  EXPECT_LE(ready, 500u + 4) << "a hit must be ready at hit_latency";
  EXPECT_EQ(cache.stats().hits, 1u);
}

TEST(CacheTiming, MissIsReadyAtTagCheckPlusBelowLatency) {
  test::MockMemory mem(100);
  Cache cache(small_cache(), &mem);
  EXPECT_EQ(cache.read(0x1000, 64, 10), 10u + 4 + 100);
  ASSERT_EQ(mem.requests.size(), 1u);
  EXPECT_EQ(mem.requests[0].at, 14u) << "the miss goes below after the tag check";
  EXPECT_EQ(mem.requests[0].bytes, 64u);
  EXPECT_EQ(mem.requests[0].addr, 0x1000u);
}

TEST(CacheTiming, MissToALineInFlightMergesIntoItsMshr) {
  test::MockMemory mem(100);
  Cache cache(small_cache(), &mem);
  Cycle first = cache.read(0x1000, 64, 0);
  Cycle second = cache.read(0x1020, 16, 50);  // same line, still in flight
  EXPECT_EQ(second, first);
  EXPECT_EQ(mem.requests.size(), 1u);
  EXPECT_EQ(cache.stats().mshr_merges, 1u);
  EXPECT_EQ(cache.read(0x1020, 16, first), first + 4) << "after the fill it is a plain hit";
}

TEST(CacheTiming, WithMshrsFullAMissWaitsExactlyUntilTheFirstCompletes) {
  test::MockMemory mem(100);
  Cache cache(small_cache(), &mem);  // 2 MSHRs
  EXPECT_EQ(cache.read(0x0000, 64, 0), 104u);
  EXPECT_EQ(cache.read(0x0040, 64, 1), 105u);
  EXPECT_EQ(cache.read(0x0080, 64, 2), 104u + 100) << "goes below when the first MSHR frees";
  ASSERT_EQ(mem.requests.size(), 3u);
  EXPECT_EQ(mem.requests[2].at, 104u);
  EXPECT_EQ(cache.stats().mshr_stall_cycles, 104u - 6) << "from its tag check to the MSHR";
  EXPECT_EQ(cache.read(0x00c0, 64, 300), 404u) << "MSHRs free again later";
}

TEST(CacheTiming, AMissAtTheCycleAnMshrFreesDoesNotWait) {
  test::MockMemory mem(100);
  Cache cache(small_cache(), &mem);
  cache.read(0x0000, 64, 0);  // MSHR busy until 104
  cache.read(0x0040, 64, 0);  // until 104
  EXPECT_EQ(cache.read(0x0080, 64, 99), 99u + 4 + 1 + 100) << "its tag check ends at 103: waits 1";
  EXPECT_EQ(cache.stats().mshr_stall_cycles, 1u);
  EXPECT_EQ(cache.read(0x00c0, 64, 100), 100u + 4 + 100) << "tag check ends at 104: no wait";
  EXPECT_EQ(cache.stats().mshr_stall_cycles, 1u);
}

TEST(CacheTiming, ReadsWaitForDataTheLevelBelowReportsLater) {
  test::MockMemory mem(0, true);
  test::RecordingClient client;
  Cache cache(small_cache(), &mem, CachePlace{0, false});
  ReadCharge charge;
  EXPECT_EQ(cache.read(0x1000, 64, 10, &client, 7, charge), kPending);
  EXPECT_EQ(cache.read(0x1010, 16, 20, &client, 8, charge), kPending) << "merges: time unknown";
  EXPECT_EQ(charge.accesses[0], 2u);
  EXPECT_EQ(charge.hits[0], 0u);
  ASSERT_EQ(mem.requests.size(), 1u);
  EXPECT_TRUE(client.done.empty()) << "nothing completes before the level below answers";
  mem.answer(0, 150);
  ASSERT_EQ(client.done.size(), 2u);
  EXPECT_EQ(client.done[0].token, 7u);
  EXPECT_EQ(client.done[0].ready, 150u);
  EXPECT_EQ(client.done[1].token, 8u);
  EXPECT_EQ(client.done[1].ready, 150u);
  EXPECT_EQ(cache.read(0x1000, 64, 100, &client, 9, charge), 150u) << "in flight, time known";
  EXPECT_EQ(cache.read(0x1000, 64, 150, &client, 9, charge), 154u) << "then a hit";
}

TEST(CacheTiming, MissesWaitingForMshrsOfUnknownEndLeaveWhenOneIsReported) {
  test::MockMemory mem(0, true);
  test::RecordingClient client;
  Cache cache(small_cache(), &mem);  // 2 MSHRs
  ReadCharge charge;
  cache.read(0x0000, 64, 0, &client, 1, charge);
  cache.read(0x0040, 64, 0, &client, 2, charge);
  cache.read(0x0080, 64, 5, &client, 3, charge);
  EXPECT_EQ(mem.requests.size(), 2u) << "no MSHR for the third miss yet";
  mem.answer(1, 300);
  ASSERT_EQ(mem.requests.size(), 3u);
  EXPECT_EQ(mem.requests[2].at, 300u) << "it takes the MSHR freed at 300";
  EXPECT_EQ(cache.stats().mshr_stall_cycles, 300u - 9);
  EXPECT_EQ(charge.dram_bytes, 3u * 64) << "as the L2, it charges what it fetches";
}

TEST(CacheTiming, MissesWaitingForAnMshrGoBelowInTheOrderTheyCame) {
  test::MockMemory mem(0, true);
  test::RecordingClient client;
  CacheConfig config = small_cache();
  config.mshrs = 1;
  Cache cache(config, &mem);
  ReadCharge charge;
  const uint32_t misses = 10000;
  for (uint32_t i = 0; i < misses; ++i) cache.read(uint64_t(i) * 64, 64, i, &client, i, charge);
  ASSERT_EQ(mem.requests.size(), 1u) << "one MSHR, whose end is not known yet";
  for (uint32_t i = 0; i < misses; ++i) {
    ASSERT_EQ(mem.requests.size(), i + 1u);
    EXPECT_EQ(mem.requests[i].addr, uint64_t(i) * 64) << "miss " << i << " went below out of order";
    mem.answer(i, 1000 + i);
  }
  ASSERT_EQ(client.done.size(), misses);
  for (uint32_t i = 0; i < misses; ++i) EXPECT_EQ(client.done[i].token, i);
}

TEST(CacheTiming, RequestSpanningTwoLinesIsReadyWithTheLaterLine) {
  test::MockMemory mem(100);
  Cache cache(small_cache(), &mem);
  cache.read(0x1000, 64, 0);
  EXPECT_EQ(cache.read(0x1020, 64, 200), 200u + 4 + 100);  // 0x1000 hits, 0x1040 misses
  EXPECT_EQ(cache.stats().accesses, 3u);
  EXPECT_EQ(cache.stats().misses, 2u);
  EXPECT_EQ(cache.stats().bytes_below, 128u);
}

TEST(CacheTiming, OnlyTheFirstMissOfALineIsCold) {
  test::MockMemory mem(10);
  Cache cache(small_cache(), &mem);  // 8 sets of 2 ways: lines 512 bytes apart share a set
  cache.track_cold_misses();
  Cycle now = 0;
  for (uint64_t addr : {0x0, 0x200, 0x400, 0x0, 0x40}) now = cache.read(addr, 64, now) + 1;
  EXPECT_EQ(cache.stats().misses, 5u) << "0x0 was evicted by 0x200 and 0x400";
  EXPECT_EQ(cache.stats().cold_misses, 4u) << "its second miss is a capacity miss, not cold";
}

TEST(CacheTiming, AbsentSharersServeTheirShareOfFirstReferences) {
  test::MockMemory mem(10);
  CacheConfig config = small_cache();
  config.size_bytes = 1 << 20;
  config.mshrs = 64;
  Cache alone(config, &mem), none(config, &mem), half(config, &mem);
  alone.track_cold_misses();
  none.share_first_references(0.0);
  half.share_first_references(0.5);
  for (uint64_t line = 0; line < 1000; ++line) {
    alone.read(line * 64, 64, 0);
    EXPECT_EQ(none.read(line * 64, 64, 0), 4u) << "another client fetched it: a hit";
    half.read(line * 64, 64, 0);
  }
  EXPECT_EQ(alone.stats().cold_misses, 1000u);
  EXPECT_EQ(none.stats().absent_fills, 1000u);
  EXPECT_EQ(none.stats().hits, 1000u);
  EXPECT_EQ(none.stats().misses, 0u);
  EXPECT_EQ(half.stats().cold_misses + half.stats().absent_fills, 1000u);
  EXPECT_NEAR(double(half.stats().cold_misses), 500.0, 50.0);
  half.read(0, 64, 100);
  EXPECT_EQ(half.stats().cold_misses + half.stats().absent_fills, 1000u) << "only first ones";
}

// Reads lines from `line` on at cycle `at`, each a first reference, until one is of the wanted
// kind (fetched here: a miss; otherwise an absent fill); returns its address.
uint64_t first_reference_of_kind(Cache& cache, uint64_t& line, Cycle at, bool fetched_here) {
  for (;; ++line) {
    uint64_t misses = cache.stats().misses;
    cache.read(line * 64, 64, at);
    if ((cache.stats().misses > misses) == fetched_here) return line++ * 64;
  }
}

TEST(CacheTiming, AnAbsentSharersFetchIsInFlightForAFetchsMeanLatency) {
  test::MockMemory mem(100);
  CacheConfig config = small_cache();
  config.size_bytes = 1 << 20;
  config.mshrs = 64;
  Cache cache(config, &mem);
  cache.share_first_references(0.5);
  uint64_t line = 0;
  uint64_t early = first_reference_of_kind(cache, line, 0, false);
  EXPECT_EQ(cache.read(early, 64, 1), 5u) << "with no fetch done yet, an absent fill is there";
  first_reference_of_kind(cache, line, 0, true);  // a fetch here: 104 cycles from its request
  uint64_t absent = first_reference_of_kind(cache, line, 1000, false);
  CacheStats before = cache.stats();
  EXPECT_EQ(cache.read(absent, 64, 1050), 1104u) << "the absent fetch is in flight: it merges";
  EXPECT_EQ(cache.read(absent, 64, 1103), 1107u) << "merged at 1103, after its own tag check";
  EXPECT_EQ(cache.stats().mshr_merges, before.mshr_merges + 2);
  EXPECT_EQ(cache.stats().hits, before.hits);
  EXPECT_EQ(cache.read(absent, 64, 1104), 1108u) << "from the fetch's latency on, a plain hit";
  EXPECT_EQ(cache.stats().hits, before.hits + 1);
  EXPECT_EQ(cache.stats().misses, before.misses) << "an absent fill never goes below";
  Cache primed(config, &mem);
  primed.share_first_references(0.5, 60);  // a fetch is taken to last 60 cycles until measured
  EXPECT_EQ(primed.read(0, 64, 0), 4u) << "line 0 is an absent fill";
  EXPECT_EQ(primed.read(0, 64, 59), 63u);
  EXPECT_EQ(primed.stats().mshr_merges, 1u) << "at 59 the absent fetch is still in flight";
  EXPECT_EQ(primed.read(0, 64, 60), 64u);
  EXPECT_EQ(primed.stats().hits, 2u) << "from 60 on, a hit";
}

TEST(CacheTiming, WarmingFillsWithoutCountingAndEvictsAsAMiss) {
  test::MockMemory mem(10);
  Cache cache(small_cache(), &mem);  // 8 sets of 2 ways: lines 512 bytes apart share a set
  cache.track_cold_misses();
  EXPECT_EQ(cache.warm(0x0, 64, 0), 1u) << "one block fetched for the absent client";
  EXPECT_EQ(cache.warm(0x0, 64, 1), 0u) << "present: nothing fetched";
  EXPECT_EQ(cache.stats().accesses + cache.stats().misses, 0u) << "warming counts no access";
  EXPECT_TRUE(mem.requests.empty()) << "nothing went below";
  EXPECT_EQ(cache.read(0x0, 64, 10), 14u) << "a warmed block hits";
  cache.read(0x200, 64, 20);
  EXPECT_EQ(cache.stats().cold_misses, 1u) << "0x0 was referenced by the warming";
  cache.warm(0x400, 64, 30);  // evicts 0x0, the least recently used of the set
  EXPECT_FALSE(cache.contains(0x0));
  EXPECT_TRUE(cache.contains(0x200));
  EXPECT_EQ(cache.warm(0x600, 64, 40, true), 0u) << "a write allocates, fetches nothing";
  cache.warm(0x800, 64, 50);
  cache.warm(0xa00, 64, 60);  // evicts the dirty 0x600
  ASSERT_EQ(mem.writes.size(), 1u);
  EXPECT_EQ(mem.writes[0].addr, 0x600u);
  EXPECT_EQ(cache.warm(kLocalMemoryBase, 64, 70), 0u) << "local memory: a refill, not a fetch";
}

TEST(CacheConfigCheck, RejectsImpossibleConfigs) {
  CacheConfig c = small_cache();
  c.line_bytes = 48;
  EXPECT_EQ(cache_config_problem(c), "line_bytes must be a power of two");
  c = small_cache();
  c.size_bytes = 1000;
  EXPECT_NE(cache_config_problem(c), "");
  c = small_cache();
  c.replacement = "plru";
  EXPECT_EQ(cache_config_problem(c), "replacement 'plru' is unknown (lru, fifo, random)");
  test::MockMemory mem(1);
  EXPECT_THROW(Cache(c, &mem), std::invalid_argument);
}

}  // namespace
}  // namespace rtsim
