// Set-associative cache with MSHRs (miss merging), one level of the RT unit's memory hierarchy
// (per-unit L1 for nodes and triangles, shared L2).
// Timing: a hit is ready hit_latency cycles after the request; a miss goes below after the tag
// check (hit_latency) and its line is ready when the level below delivers it. A request to a
// line whose miss is still in flight merges into that MSHR and is ready with it. With all
// MSHRs busy, a new miss waits for the earliest one to finish (counted as stall cycles).
// Requests spanning several lines access them in the same cycle. Allocate on miss, read only
// (the RT unit never writes BVH data; stack spills are modelled as DRAM traffic).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <queue>
#include <string>
#include <unordered_set>
#include <vector>

#include "model/mem/memory_level.h"
#include "model/mem/replacement.h"

namespace rtsim {

struct CacheConfig {
  uint64_t size_bytes = 16 * 1024;  // bytes: data capacity
  uint32_t line_bytes = 64;         // bytes: line size, a power of two
  uint32_t ways = 4;                // associativity: lines per set
  std::string replacement = "lru";  // replacement policy: lru, fifo or random
  uint32_t hit_latency = 4;         // cycles: from request to data on a hit
  uint32_t mshrs = 8;               // count: line misses in flight at once
};

// Why the config is impossible (empty if it is fine): sizes, powers of two, known policy.
std::string cache_config_problem(const CacheConfig& config);

struct CacheStats {
  uint64_t accesses = 0;           // line accesses (a request spanning 2 lines counts 2)
  uint64_t hits = 0;               // line present and ready
  uint64_t misses = 0;             // line absent: a request went below
  uint64_t cold_misses = 0;        // misses of lines never referenced before (if tracked)
  uint64_t absent_fills = 0;       // first references served by an absent sharer (counted as hits)
  uint64_t mshr_merges = 0;        // line in flight: merged into its MSHR
  uint64_t mshr_stall_cycles = 0;  // cycles misses waited for a free MSHR
  uint64_t evictions = 0;          // valid lines replaced
  uint64_t bytes_below = 0;        // bytes requested from the level below
};

class Cache : public MemoryLevel {
 public:
  // Throws std::invalid_argument for an impossible config (see cache_config_problem).
  Cache(const CacheConfig& config, MemoryLevel* below);

  Cycle read(uint64_t addr, uint32_t bytes, Cycle now) override;
  // Whether the line holding addr is present (in flight counts); changes nothing.
  bool contains(uint64_t addr) const;
  // Keeps a set of every line referenced, to count cold (compulsory) misses; without it
  // cold_misses stays 0. Costs a hash insert per miss: the simulator tracks its L2 only.
  void track_cold_misses() { track_cold_ = true; }
  bool tracks_cold_misses() const { return track_cold_; }
  // For a scale model (model/fidelity/scaled_level.h): this cache stands in for a shared cache
  // of which the simulation drives only `own_share` of the clients. The first reference to a
  // line then goes below with probability own_share (decided by a hash of the line address);
  // otherwise one of the absent clients fetched it earlier, and it is a hit (absent_fills).
  void share_first_references(double own_share) {
    own_share_ = own_share;
    track_cold_ = true;
  }
  const CacheStats& stats() const { return stats_; }
  const CacheConfig& config() const { return config_; }

 private:
  struct Line {
    uint64_t tag = 0;
    Cycle ready = 0;
    bool valid = false;
  };
  Cycle access_line(uint64_t line, Cycle now);
  void install(uint32_t set, Line* ways, const Line& line);  // evicting a victim if needed
  Cycle reserve_mshr(Cycle now);

  CacheConfig config_;
  MemoryLevel* below_;
  uint32_t sets_;
  std::vector<Line> lines_;  // sets_ x ways, set-major
  std::unique_ptr<ReplacementPolicy> policy_;
  std::priority_queue<Cycle, std::vector<Cycle>, std::greater<Cycle>> in_flight_;
  std::unordered_set<uint64_t> held_lines_;  // every line ever referenced: tells cold misses
  bool track_cold_ = false;
  double own_share_ = 1.0;
  CacheStats stats_;
};

}  // namespace rtsim
