// The cache's write side with a mock memory below it: writes allocate without a fetch,
// write-back sends dirty blocks below on eviction, write-through sends every write at once;
// local memory is counted apart.
#include <gtest/gtest.h>

#include "mock_memory.h"
#include "model/mem/cache.h"

namespace rtsim {
namespace {

CacheConfig small_cache() {
  CacheConfig c;
  c.size_bytes = 1024;  // 8 sets of 2 ways of 64-byte lines
  c.line_bytes = 64;
  c.ways = 2;
  c.hit_latency = 4;
  c.mshrs = 4;
  return c;
}

constexpr uint64_t kLocal = kLocalMemoryBase;
constexpr uint64_t kSetStride = 8 * 64;  // addresses this far apart share a set

TEST(CacheWrites, AWriteAllocatesWithoutAFetchAndReadsBackAsAHit) {
  test::MockMemory mem(100);
  Cache cache(small_cache(), &mem);
  cache.write(kLocal + 8, 16, 0);
  EXPECT_TRUE(mem.requests.empty()) << "write-validate: nothing is fetched";
  EXPECT_TRUE(mem.writes.empty()) << "write-back: nothing goes below yet";
  EXPECT_EQ(cache.read(kLocal + 8, 16, 10), 14u);
  EXPECT_EQ(cache.stats().writes, 1u);
  EXPECT_EQ(cache.stats().write_misses, 1u);
  EXPECT_EQ(cache.stats().local_reads, 1u);
  EXPECT_EQ(cache.stats().local_misses, 0u);
  EXPECT_EQ(cache.stats().hits, 1u);
}

TEST(CacheWrites, ADirtyLineGoesBelowWhenEvictedAndACleanOneDoesNot) {
  test::MockMemory mem(100);
  Cache cache(small_cache(), &mem);
  cache.write(kLocal, 24, 0);
  cache.read(0x1000 * kSetStride, 64, 10);  // the set's second way
  cache.read(0x2000 * kSetStride, 64, 20);  // evicts the written line (least recently used)
  ASSERT_EQ(mem.writes.size(), 1u);
  EXPECT_EQ(mem.writes[0].addr, kLocal);
  EXPECT_EQ(mem.writes[0].bytes, 64u) << "the whole block";
  EXPECT_EQ(mem.writes[0].at, 24u) << "after the evicting miss's tag check";
  cache.read(0x3000 * kSetStride, 64, 30);  // evicts a clean line
  EXPECT_EQ(mem.writes.size(), 1u);
  EXPECT_EQ(cache.stats().writebacks, 1u);
  EXPECT_EQ(cache.stats().writeback_bytes, 64u);
  EXPECT_EQ(cache.read(kLocal, 24, 40), 40u + 4 + 100) << "evicted: read back from below";
  EXPECT_EQ(cache.stats().local_misses, 1u);
}

TEST(CacheWrites, WriteThroughSendsEveryWriteBelowAtOnce) {
  test::MockMemory mem(100);
  CacheConfig c = small_cache();
  c.write_back = false;
  Cache cache(c, &mem);
  cache.write(kLocal + 100, 24, 5);
  ASSERT_EQ(mem.writes.size(), 1u);
  EXPECT_EQ(mem.writes[0].addr, kLocal + 100);
  EXPECT_EQ(mem.writes[0].bytes, 24u);
  EXPECT_EQ(mem.writes[0].at, 9u);
  EXPECT_EQ(cache.read(kLocal + 100, 24, 10), 14u) << "allocated too";
  cache.read(0x1000 * kSetStride + 64, 64, 20);
  cache.read(0x2000 * kSetStride + 64, 64, 30);
  EXPECT_EQ(mem.writes.size(), 1u) << "nothing dirty to write back";
}

TEST(CacheWrites, AWriteThroughSpanningTwoLinesGoesBelowAsTwo) {
  test::MockMemory mem(100);
  CacheConfig c = small_cache();
  c.write_back = false;
  Cache cache(c, &mem);
  cache.write(kLocal + 56, 16, 0);  // 8 bytes in each of two lines
  ASSERT_EQ(mem.writes.size(), 2u) << "a sliced level below places the lines apart";
  EXPECT_EQ(mem.writes[0].addr, kLocal + 56);
  EXPECT_EQ(mem.writes[0].bytes, 8u);
  EXPECT_EQ(mem.writes[1].addr, kLocal + 64);
  EXPECT_EQ(mem.writes[1].bytes, 8u);
}

TEST(CacheWrites, SectoredLinesWriteBackOnlyTheirDirtySectors) {
  test::MockMemory mem(100);
  CacheConfig c = small_cache();
  c.sector_bytes = 16;
  Cache cache(c, &mem);
  cache.write(kLocal + 16, 8, 0);
  cache.read(kLocal, 16, 5);  // another sector of the line: fetched, clean
  cache.read(0x1000 * kSetStride, 16, 10);
  cache.read(0x2000 * kSetStride, 16, 20);
  ASSERT_EQ(mem.writes.size(), 1u);
  EXPECT_EQ(mem.writes[0].addr, kLocal + 16);
  EXPECT_EQ(mem.writes[0].bytes, 16u);
}

}  // namespace
}  // namespace rtsim
