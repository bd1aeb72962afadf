// LruStackSets (model/mem/stack_distance.h): hand-made streams whose stack distances are known
// give the exact curve; on random streams with sectors, writes and slices it counts the same
// misses and write-backs as the cycle model's Cache at every associativity.
#include "model/mem/stack_distance.h"

#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <vector>

#include "model/mem/cache.h"
#include "model/mem/slice_hash.h"
#include "tests/mem/mock_memory.h"

namespace rtsim {
namespace {

constexpr uint64_t kLine = 128;

TEST(StackDistance, HandMadeStreamGivesTheExactCurve) {
  // One set, lines of one block. A B C A D B A: A, B, C, D cold; then A at distance 2
  // (B, C since), B at 3 (C, A, D), A at 2 (D, B).
  LruStackSets s({kLine, kLine, 1, 1}, 8);
  for (uint64_t line : {0, 1, 2, 0, 3, 1, 0}) s.reference(line * kLine, false);
  s.finish();
  EXPECT_EQ(s.reads(), 7u);
  std::vector<uint64_t> expected{0, 0, 2, 1, 0, 0, 0, 0, 4};
  EXPECT_EQ(s.read_distances(), expected);
  EXPECT_EQ(s.read_misses(1), 7u);
  EXPECT_EQ(s.read_misses(2), 7u);
  EXPECT_EQ(s.read_misses(3), 5u);
  EXPECT_EQ(s.read_misses(4), 4u);
  EXPECT_EQ(s.read_misses(8), 4u);
}

TEST(StackDistance, SectorHitsOnlyIfItsLineStayed) {
  // Lines of 4 sectors. A0 B0 A1 A0: A1 is a first reference (a miss at every size); A0's line
  // was 1 deep at A1, so one way lost it to B (a miss), two ways kept it (a hit).
  LruStackSets s({kLine, 32, 1, 1}, 4);
  for (uint64_t addr : {0 * kLine, 1 * kLine, 0 * kLine + 32, 0 * kLine}) s.reference(addr, false);
  s.finish();
  EXPECT_EQ(s.read_misses(1), 4u);
  EXPECT_EQ(s.read_misses(2), 3u);
}

TEST(StackDistance, DirtyBlockWrittenBackOnlyWhereItsLineIsEvicted) {
  // Write A, read B, write A, read B, write C. One way: B evicts A's first write; C evicts A's
  // second (A ends 2 deep, below C and B): 2 write-backs. Two ways: only C evicts A: 1. Three: 0.
  LruStackSets s({kLine, kLine, 1, 1}, 4);
  s.reference(0, true);
  s.reference(kLine, false);
  s.reference(0, true);
  s.reference(kLine, false);
  s.reference(2 * kLine, true);
  s.finish();
  EXPECT_EQ(s.writes(), 3u);
  EXPECT_EQ(s.writebacks(1), 2u);  // C's write is never evicted
  EXPECT_EQ(s.writebacks(2), 1u);
  EXPECT_EQ(s.writebacks(3), 0u);
}

struct Reference {
  uint64_t addr;
  bool write;
};

std::vector<Reference> random_stream(size_t n, uint64_t lines, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<Reference> out;
  for (size_t i = 0; i < n; ++i) {
    uint64_t line = rng() % lines;
    if (rng() % 4 == 0) line = rng() % (lines / 8 + 1);  // a hot part, so there is reuse
    out.push_back({line * kLine + (rng() % 4) * 32, rng() % 5 == 0});
  }
  return out;
}

// The stream through `slices` Caches of `sets` sets and `ways` ways, routed as the cycle model's
// L2 routes lines; returns the summed stats.
CacheStats through_caches(const std::vector<Reference>& stream, uint32_t slices, uint64_t sets,
                          uint32_t ways, uint32_t sector) {
  test::MockMemory below(1);
  CacheConfig c;
  c.size_bytes = sets * kLine * ways;
  c.line_bytes = kLine;
  c.sector_bytes = sector;
  c.ways = ways;
  c.mshrs = 1;
  std::vector<std::unique_ptr<Cache>> caches;
  for (uint32_t i = 0; i < slices; ++i) caches.push_back(std::make_unique<Cache>(c, &below));
  Cycle now = 0;
  for (const Reference& r : stream) {
    Cache& cache = *caches[slice_of_line(r.addr / kLine, slices)];
    uint64_t block = r.addr & ~uint64_t(cache.block_bytes() - 1);
    now += 1000;
    if (r.write)
      cache.write(block, cache.block_bytes(), now);
    else
      cache.read(block, cache.block_bytes(), now);
  }
  CacheStats sum;
  for (const auto& cache : caches) sum += cache->stats();
  return sum;
}

TEST(StackDistance, EqualsTheCacheAtEveryAssociativity) {
  for (uint32_t slices : {1u, 4u})
    for (uint64_t sets : {1u, 3u, 8u})
      for (uint32_t sector : {0u, 32u}) {
        std::vector<Reference> stream = random_stream(20000, 300, slices * 31 + sets + sector);
        LruStackSets s({kLine, sector ? sector : uint32_t(kLine), slices, sets}, 16);
        for (const Reference& r : stream) s.reference(r.addr, r.write);
        s.finish();
        for (uint32_t ways : {1u, 2u, 4u, 7u, 16u}) {
          CacheStats c = through_caches(stream, slices, sets, ways, sector);
          SCOPED_TRACE(testing::Message() << slices << " slices, " << sets << " sets, " << ways
                                          << " ways, sector " << sector);
          EXPECT_EQ(s.reads(), c.accesses);
          EXPECT_EQ(s.read_misses(ways), c.misses);
          EXPECT_EQ(s.writebacks(ways), c.writebacks);
          EXPECT_GT(c.misses, 0u);
        }
      }
}

TEST(StackDistance, RejectsImpossibleShapes) {
  EXPECT_THROW(LruStackSets({kLine, 32, 1, 1}, 0), std::invalid_argument);
  EXPECT_THROW(LruStackSets({kLine, 32, 1, 1}, 255), std::invalid_argument);
  EXPECT_THROW(LruStackSets({kLine, 4, 1, 1}, 8), std::invalid_argument);  // 32 blocks a line
  EXPECT_THROW(LruStackSets({kLine, 32, 0, 1}, 8), std::invalid_argument);
}

}  // namespace
}  // namespace rtsim
