// MiniCache (model/mem/mini_cache.h): at rate 1 it is the full sliced L2, count for count; at
// rate R it sees about 1 line in R and estimates the full cache's miss ratio within its interval.
#include "model/mem/mini_cache.h"

#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <vector>

#include "model/mem/slice_hash.h"
#include "model/mem/stack_distance.h"
#include "tests/mem/mock_memory.h"

namespace rtsim {
namespace {

constexpr uint64_t kLine = 128;

CacheConfig l2(uint64_t size, uint32_t ways) {
  CacheConfig c;
  c.size_bytes = size;
  c.line_bytes = kLine;
  c.sector_bytes = 32;
  c.ways = ways;
  return c;
}

struct Reference {
  uint64_t addr;
  bool write;
};

// Lines drawn with a skew (many cold, some hot), a block of each, 1 in 6 a write.
std::vector<Reference> skewed_stream(size_t n, uint64_t lines, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<Reference> out;
  for (size_t i = 0; i < n; ++i) {
    uint64_t line = rng() % lines;
    line = line * line / lines;  // low lines more often
    out.push_back({line * kLine + (rng() % 4) * 32, rng() % 6 == 0});
  }
  return out;
}

TEST(MiniCache, RateOneIsTheFullCache) {
  const uint32_t slices = 4, ways = 4;
  const uint64_t size = 64 * kLine * ways;  // 16 sets per slice
  std::vector<Reference> stream = skewed_stream(30000, 2000, 3);
  test::MockMemory below(1);
  CacheConfig slice = l2(size / slices, ways);
  std::vector<std::unique_ptr<Cache>> full;
  for (uint32_t i = 0; i < slices; ++i) full.push_back(std::make_unique<Cache>(slice, &below));
  MiniCache mini(l2(size, ways), slices, 1);
  Cycle now = 0;
  for (const Reference& r : stream) {
    Cache& c = *full[slice_of_line(r.addr / kLine, slices)];
    now += 1000;
    r.write ? c.write(r.addr, 32, now) : void(c.read(r.addr, 32, now));
    mini.reference(r.addr, r.write);
  }
  CacheStats want;
  for (const auto& c : full) want += c->stats();
  CacheStats got = mini.stats();
  EXPECT_EQ(got.accesses, want.accesses);
  EXPECT_EQ(got.misses, want.misses);
  EXPECT_EQ(got.writebacks, want.writebacks);
  EXPECT_EQ(got.evictions, want.evictions);
  EXPECT_DOUBLE_EQ(mini.miss_ratio().value, double(want.misses) / double(want.accesses));
  EXPECT_EQ(mini.miss_ratio().ci95, 0.0);  // every line seen: nothing left to chance
  EXPECT_DOUBLE_EQ(mini.dram_blocks_per_read().value,
                   double(want.misses + want.writebacks) / double(want.accesses));
}

TEST(MiniCache, SampledMissRatioLandsNearTheExactOne) {
  const uint32_t slices = 4, ways = 8, rate = 8;
  const uint64_t size = 256 * kLine * ways;  // 64 sets per slice; the miniature has 8
  std::vector<Reference> stream = skewed_stream(400000, 60000, 5);
  LruStackSets exact({kLine, 32, slices, 64}, ways);
  MiniCache mini(l2(size, ways), slices, rate);
  uint64_t sampled_lines = 0;
  for (const Reference& r : stream) {
    exact.reference(r.addr, r.write);
    mini.reference(r.addr, r.write);
  }
  for (uint64_t line = 0; line < 60000; ++line) sampled_lines += MiniCache::sampled(line, rate);
  EXPECT_NEAR(double(sampled_lines) / 60000, 1.0 / rate, 0.01);
  exact.finish();
  double truth = double(exact.read_misses(ways)) / double(exact.reads());
  MiniEstimate est = mini.miss_ratio();
  EXPECT_GT(truth, 0.2);  // the stream does not fit: capacity misses matter
  EXPECT_GT(est.ci95, 0.0);
  EXPECT_LT(est.ci95, 0.1);
  EXPECT_NEAR(est.value, truth, std::max(est.ci95, 0.01));
}

TEST(MiniCache, RefusesARateTheSetsDoNotDivideBy) {
  EXPECT_NE(mini_cache_problem(l2(16 * kLine * 4, 4), 4, 32), "");  // 16 sets in all
  EXPECT_EQ(mini_cache_problem(l2(16 * kLine * 4, 4), 4, 16), "");  // 1 set in 1 slice
  EXPECT_THROW(MiniCache(l2(16 * kLine * 4, 4), 4, 3), std::invalid_argument);
}

}  // namespace
}  // namespace rtsim
