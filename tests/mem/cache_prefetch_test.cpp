// Prefetches into a cache with a mock memory below: what goes below and when, which reads count
// as useful or late, redundant and useless prefetches, and MSHRs shared with demand misses.
#include <gtest/gtest.h>

#include "mock_memory.h"
#include "model/mem/cache.h"

namespace rtsim {
namespace {

CacheConfig small_cache() {
  CacheConfig c;
  c.size_bytes = 1024;  // 8 sets of 2 ways, 64-byte lines
  c.line_bytes = 64;
  c.ways = 2;
  c.hit_latency = 4;
  c.mshrs = 4;
  return c;
}

TEST(CachePrefetch, SendsEachAbsentBlockBelowAfterTheTagCheckAndNobodyWaits) {
  test::MockMemory mem(100, true);
  Cache cache(small_cache(), &mem);
  cache.prefetch(0x1000, 192, 10);  // three lines
  ASSERT_EQ(mem.requests.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(mem.requests[i].addr, 0x1000u + 64 * i);
    EXPECT_EQ(mem.requests[i].at, 14u);
    mem.answer(i, 114);  // no client of the cache is told
  }
  EXPECT_EQ(cache.stats().prefetches, 3u);
  EXPECT_EQ(cache.stats().misses, 0u) << "misses count demand reads only";
  EXPECT_EQ(cache.stats().accesses, 0u);
  EXPECT_EQ(cache.stats().bytes_below, 192u);
}

TEST(CachePrefetch, AReadOfAPrefetchedBlockIsUsefulAndLateWhileItIsInFlight) {
  test::MockMemory mem(100);
  Cache cache(small_cache(), &mem);
  cache.prefetch(0x1000, 128, 0);  // ready at 104
  EXPECT_EQ(cache.read(0x1000, 64, 50), 104u) << "merges into the prefetch's MSHR";
  EXPECT_EQ(cache.read(0x1040, 64, 200), 204u) << "a plain hit once the data is there";
  EXPECT_EQ(cache.read(0x1040, 64, 300), 304u);
  const CacheStats& s = cache.stats();
  EXPECT_EQ(s.prefetch_useful, 2u) << "the first read of each block only";
  EXPECT_EQ(s.prefetch_late, 1u);
  EXPECT_EQ(s.misses, 0u);
  EXPECT_EQ(mem.requests.size(), 2u);
}

TEST(CachePrefetch, PresentBlocksAreRedundantAndEvictedUnusedOnesUseless) {
  test::MockMemory mem(10);
  Cache cache(small_cache(), &mem);
  cache.read(0x0000, 64, 0);
  cache.prefetch(0x0000, 128, 20);  // line 0 present, line 1 fetched
  EXPECT_EQ(cache.stats().prefetch_redundant, 1u);
  EXPECT_EQ(cache.stats().prefetches, 1u);
  // Set 1 (line 0x40) takes two more lines: the prefetched one, unread, is the LRU victim.
  cache.read(0x0240, 64, 100);
  cache.read(0x0440, 64, 200);
  EXPECT_EQ(cache.stats().prefetch_useless, 1u);
  EXPECT_EQ(cache.stats().prefetch_useful, 0u);
}

TEST(CachePrefetch, APrefetchedBlockIsReferencedSoALaterMissOfItIsNotCompulsory) {
  test::MockMemory mem(10);
  Cache cache(small_cache(), &mem);
  cache.track_cold_misses();
  cache.prefetch(0x0040, 64, 0);  // set 1
  cache.read(0x0240, 64, 100);    // set 1 fills
  cache.read(0x0440, 64, 200);    // and evicts the prefetched line, unread
  cache.read(0x0040, 64, 300);    // a miss, but not a first reference
  EXPECT_EQ(cache.stats().misses, 3u);
  EXPECT_EQ(cache.stats().cold_misses, 2u);
}

TEST(CachePrefetch, PrefetchesTakeMshrsInTurnWithDemandMisses) {
  test::MockMemory mem(100);
  Cache cache(small_cache(), &mem);  // 4 MSHRs
  cache.prefetch(0x1000, 256, 0);    // four blocks: every MSHR until 104
  EXPECT_EQ(cache.read(0x2000, 64, 1), 104u + 100) << "the demand miss waits for an MSHR";
  EXPECT_EQ(cache.stats().mshr_stall_cycles, 104u - 5);
}

}  // namespace
}  // namespace rtsim
