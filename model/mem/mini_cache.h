// A miniature of the shared L2 for miss-ratio estimates, after SHARDS and miniature simulation
// (Waldspurger, Park, Garthwaite and Ahmad, "Efficient MRC Construction with SHARDS", FAST 2015;
// Waldspurger, Saemundsson, Ahmad and Park, "Cache Modeling and Optimization using Miniature
// Simulations", USENIX ATC 2017). Only the lines a hash selects, 1 in `rate`, reach it, and it
// has 1/rate of the full cache's sets (same ways, line, sectors and policy: real Cache slices,
// model/mem/cache.h, no timing), so each of its sets sees the load one set of the full cache
// sees; its miss ratio estimates the full cache's. At rate 1 it is the full cache: the cycle
// model's slices (model/sc/shared_levels_module.h), functionally. Fetches and write-backs are
// counted per sampled line, so the estimates come with a 95% interval that treats the sampled
// lines as a random sample of clusters (a ratio estimator, Cochran, Sampling Techniques, 3rd
// ed., 6.7); it covers which lines the hash chose, not how the miniature's sets differ.
#pragma once

#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "model/mem/cache.h"

namespace rtsim {

// Why a miniature at this rate cannot be built (empty if it can): the full cache's sets, over all
// slices, must divide by rate. The miniature keeps the slices while each keeps a set, then has
// fewer slices of one set each.
std::string mini_cache_problem(const CacheConfig& full, uint32_t slices, uint32_t rate);

struct MiniEstimate {
  double value = 0;  // per read: misses, or DRAM blocks (misses plus write-backs)
  double ci95 = 0;   // half-width of its 95% interval
};

class MiniCache {
 public:
  // full: the whole L2 (all slices); throws std::invalid_argument where mini_layout_problem says.
  MiniCache(const CacheConfig& full, uint32_t slices, uint32_t rate);
  MiniCache(const MiniCache&) = delete;
  MiniCache& operator=(const MiniCache&) = delete;

  // Whether the hash selects the line at this rate (independent of the slice hash).
  static bool sampled(uint64_t line, uint32_t rate);
  // A reference to one block of a line; ignored unless sampled.
  void reference(uint64_t addr, bool write);

  uint32_t rate() const { return rate_; }
  CacheStats stats() const;  // of the miniature, summed over its slices
  // Per block read of the sampled lines: its misses, and its misses plus write-backs.
  MiniEstimate miss_ratio() const { return estimate(false); }
  MiniEstimate dram_blocks_per_read() const { return estimate(true); }

 private:
  struct LineCounts {
    uint64_t reads = 0, misses = 0, writebacks = 0;
  };
  // Below the slices: counts each fetch and write-back against its line, answers at once.
  struct Counter : MemoryTarget {
    explicit Counter(MiniCache& cache) : cache(cache) {}
    Cycle read(uint64_t addr, uint32_t, Cycle at, ReadClient*, uint64_t, ReadCharge&) override;
    void write(uint64_t addr, uint32_t, Cycle) override;
    MiniCache& cache;
  };
  MiniEstimate estimate(bool with_writebacks) const;

  uint32_t rate_, line_shift_;
  Counter below_{*this};
  std::vector<std::unique_ptr<Cache>> slices_;
  std::unordered_map<uint64_t, LineCounts> lines_;
  Cycle now_ = 0;
};

}  // namespace rtsim
