// Set-associative cache with MSHRs (miss merging): one level of the RT unit's memory hierarchy
// (the per-unit L1 for nodes, triangles and stack refills; the shared L2).
// Timing: a hit is ready hit_latency cycles after the request. A miss is sent below after the
// tag check (hit_latency), when it has an MSHR: with all MSHRs busy it waits until the first of
// them is freed by its data, counted as MSHR stall cycles; its line is ready when the level
// below delivers it. A request to a line whose miss is still in flight merges into that MSHR
// and is ready with it (not before its own tag check). MSHR occupancy is kept per MSHR as the
// cycle its data arrives, so a request sees the MSHRs busy at its own cycle, not later ones.
// The level below may answer at once or later (MemoryTarget); so may this cache: a read that
// waits for data of unknown time returns kPending and completes through its client.
// Requests spanning several lines access them in the same cycle. Allocate on miss; reads only:
// writes (stack spills) pass below without allocation (write-around), hit_latency cycles
// after they arrive, as a miss does.
#pragma once

#include <cstdint>
#include <deque>
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

// Which counters of a ReadCharge a level fills: its own accesses and hits; the L2, as the last
// cache level, also the bytes it fetches from DRAM.
enum class CacheRole : uint8_t { L1, L2 };

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
  uint64_t write_bytes = 0;        // bytes written around this level (stack spills)
};

class Cache : public MemoryTarget, private ReadClient {
 public:
  // Throws std::invalid_argument for an impossible config (see cache_config_problem).
  Cache(const CacheConfig& config, MemoryTarget* below, CacheRole role = CacheRole::L2);

  Cycle read(uint64_t addr, uint32_t bytes, Cycle at, ReadClient* client, uint64_t token,
             ReadCharge& charge) override;
  // A read over levels that all answer at once (unit tests, the cache fidelity level).
  // Throws std::logic_error if it would have to wait.
  Cycle read(uint64_t addr, uint32_t bytes, Cycle at);
  void write(uint64_t addr, uint32_t bytes, Cycle at) override;

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
  static constexpr uint32_t kNone = ~0u;
  struct Line {
    uint64_t tag = 0;
    Cycle ready = 0;        // kPending: its miss (below) has not learnt its data's cycle
    uint32_t miss = kNone;  // that miss, while ready is kPending
    bool valid = false;
  };
  struct Waiter {
    ReadClient* client;
    uint64_t token;
    Cycle earliest;  // its own tag check: the data cannot be ready before
    uint32_t next;   // the next waiter of the same miss (kNone: the last)
  };
  struct Miss {
    uint64_t line = 0;
    uint32_t set = 0, way = 0;
    Cycle send = 0;  // the cycle it may go below (after the tag check)
    ReadCharge charge;
    uint32_t first = kNone, last = kNone;  // its waiters, in order: the first made the miss
  };
  // A read of several lines that waits: its client, and the lines it still waits for. Its
  // lines' misses report to join_, which completes the read with the last of them.
  struct Request {
    ReadClient* client = nullptr;
    uint64_t token = 0;
    uint32_t lines = 0;
    Cycle ready = 0;
    ReadCharge charge;
  };
  struct Join : ReadClient {
    explicit Join(Cache& cache) : cache(cache) {}
    void read_done(uint64_t request, Cycle ready, const ReadCharge& charge) override {
      cache.complete_part(uint32_t(request), ready, charge);
    }
    Cache& cache;
  };
  struct Caller {  // the read being served; a read of several lines gets a Request to wait
    ReadClient* client;
    uint64_t token;
    bool several_lines;
    uint32_t request;
  };

  // A line's ready cycle, or kPending once the caller waits for it.
  Cycle access_line(uint64_t line, Cycle at, Caller& caller, ReadCharge& charge);
  void wait_for(uint32_t miss, Caller& caller, Cycle earliest);
  void add_waiter(uint32_t miss, const Waiter& waiter);
  Cycle miss(uint64_t line, uint32_t set, Line* ways, Cycle at, Caller& caller, ReadCharge& charge);
  // Sends a miss below at `at` (its MSHR taken); the below's answer: a cycle, or kPending.
  Cycle issue(uint32_t miss, Cycle at);
  void read_done(uint64_t miss, Cycle ready, const ReadCharge& charge) override;
  void complete_part(uint32_t request, Cycle ready, const ReadCharge& charge);
  uint32_t install(uint32_t set, Line* ways, const Line& line);  // evicting a victim if needed
  template <class T>
  static uint32_t take(std::vector<T>& pool, std::vector<uint32_t>& free);

  // Set and tag of a line number: shifts and masks for a power-of-two set count (divisions
  // are slow on the hot path), divisions otherwise.
  uint32_t set_of(uint64_t line) const {
    return uint32_t(set_shift_ ? line & (sets_ - 1) : line % sets_);
  }
  uint64_t tag_of(uint64_t line) const { return set_shift_ ? line >> set_shift_ : line / sets_; }

  CacheConfig config_;
  MemoryTarget* below_;
  CacheRole role_;
  uint32_t sets_;
  uint32_t set_shift_ = 0;   // log2(sets_) if sets_ is a power of two above 1, else 0
  uint32_t line_shift_ = 0;  // log2(line_bytes)
  std::vector<Line> lines_;  // sets_ x ways, set-major
  std::unique_ptr<ReplacementPolicy> policy_;
  // The cycles the MSHRs not holding a miss are free from, earliest first. An MSHR whose miss
  // has not learnt its data's cycle is in none of them.
  std::priority_queue<Cycle, std::vector<Cycle>, std::greater<Cycle>> free_mshrs_;
  std::vector<Miss> misses_;
  std::vector<Waiter> waiters_;  // the waiters of all misses, in lists through Waiter::next
  std::vector<uint32_t> free_waiters_;
  std::vector<uint32_t> free_misses_;
  std::deque<uint32_t> waiting_;  // misses for which every MSHR's end was unknown
  std::vector<Request> requests_;
  std::vector<uint32_t> free_requests_;
  Join join_{*this};
  std::unordered_set<uint64_t> held_lines_;  // every line ever referenced: tells cold misses
  bool track_cold_ = false;
  double own_share_ = 1.0;
  CacheStats stats_;
};

}  // namespace rtsim
