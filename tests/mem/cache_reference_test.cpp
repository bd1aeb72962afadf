// The cache's hits and misses match a simple reference model (per set, a list of tags in
// recency or insertion order) on seeded random address streams with locality.
#include <gtest/gtest.h>

#include <algorithm>
#include <list>
#include <vector>

#include "mock_memory.h"
#include "model/mem/cache.h"

namespace rtsim {
namespace {

class ReferenceCache {
 public:
  ReferenceCache(const CacheConfig& c, bool lru)
      : c_(c), lru_(lru), sets_(c.size_bytes / (c.line_bytes * c.ways)), tags_(sets_) {}
  bool access(uint64_t addr) {
    uint64_t line = addr / c_.line_bytes;
    auto& set = tags_[line % sets_];
    auto it = std::find(set.begin(), set.end(), line);
    if (it != set.end()) {
      if (lru_) set.splice(set.begin(), set, it);
      return true;
    }
    if (set.size() == c_.ways) set.pop_back();
    set.push_front(line);
    return false;
  }

 private:
  CacheConfig c_;
  bool lru_;
  uint64_t sets_;
  std::vector<std::list<uint64_t>> tags_;
};

uint64_t next_random(uint64_t& state) {
  state ^= state << 13;
  state ^= state >> 7;
  state ^= state << 17;
  return state;
}

void compare_with_reference(const CacheConfig& config, uint64_t seed) {
  test::MockMemory mem(10);
  Cache cache(config, &mem);
  ReferenceCache reference(config, config.replacement == "lru");
  uint64_t state = seed, hot = 0;
  Cycle now = 0;
  for (int i = 0; i < 20000; ++i) {
    uint64_t r = next_random(state);
    if (r % 8 == 0) hot = next_random(state) % (1 << 20);
    uint64_t addr = ((r % 4 == 0) ? next_random(state) % (1 << 22) : hot + (r >> 8) % 2048) & ~3ull;
    uint64_t hits_before = cache.stats().hits;
    now += 100;  // far apart: every miss has completed, so none merges
    cache.read(addr, 4, now);
    bool hit = cache.stats().hits > hits_before;
    ASSERT_EQ(hit, reference.access(addr)) << "access " << i << " addr " << addr << " ways "
                                           << config.ways << " " << config.replacement;
  }
  EXPECT_GT(cache.stats().hits, 1000u) << "the stream should have locality";
  EXPECT_GT(cache.stats().misses, 1000u);
}

TEST(CacheReference, LruMatchesOnRandomStreams) {
  for (uint32_t ways : {1u, 2u, 4u, 8u, 16u}) {
    CacheConfig c;
    c.size_bytes = 8192;
    c.ways = ways;
    compare_with_reference(c, 12345 + ways);
  }
}

TEST(CacheReference, FifoMatchesOnRandomStreams) {
  for (uint32_t ways : {2u, 4u, 8u}) {
    CacheConfig c;
    c.size_bytes = 4096;
    c.line_bytes = 32;
    c.ways = ways;
    c.replacement = "fifo";
    compare_with_reference(c, 999 + ways);
  }
}

TEST(CacheReference, RandomReplacementIsRepeatable) {
  CacheConfig c;
  c.replacement = "random";
  test::MockMemory mem(10);
  Cache a(c, &mem), b(c, &mem);
  uint64_t state = 7;
  for (int i = 0; i < 5000; ++i) {
    uint64_t addr = next_random(state) % (1 << 18);
    a.read(addr, 4, Cycle(i) * 50);
    b.read(addr, 4, Cycle(i) * 50);
  }
  EXPECT_EQ(a.stats().hits, b.stats().hits);
  EXPECT_GT(a.stats().evictions, 0u);
}

}  // namespace
}  // namespace rtsim
