// Set-associative cache with banks, a data port, sectors and MSHRs (miss merging): one level of
// the RT unit's memory hierarchy (the per-unit L1 for nodes, triangles and stack refills; the
// shared L2).
// Timing. A request to a line first takes a port of the line's bank (lines are interleaved over
// `banks`; each bank takes `bank_ports` lookups a cycle, a further one waits for the next cycle)
// and passes the level's data port (`bytes_per_cycle`: the bytes it moves within the line, one
// request after the other). From that cycle a hit is ready hit_latency cycles later. A miss is
// sent below after the tag check (hit_latency), when it has an MSHR: with all MSHRs busy it waits
// until the first of them is freed by its data, counted as MSHR stall cycles; its block is
// ready when the level below delivers it. A request to a block whose miss is still in flight
// merges into that MSHR and is ready with it (not before its own tag check); once `merge_limit`
// requests have merged, a further one replays after the data arrives (one more hit_latency).
// MSHR occupancy is kept per MSHR as the cycle its data arrives, so a request sees the MSHRs
// busy at its own cycle, not later ones. Lines may be sectored: a miss fetches only the
// sectors (blocks) a request needs. The level below may answer at once or later (MemoryTarget);
// so may this cache: a read that waits for data of unknown time returns kPending and completes
// through its client.
// Prefetches (treelet prefetching, model/sched/treelet_prefetcher.h) fetch the absent blocks of
// a range as misses with no requester, line by line through the banks and data port: they take
// MSHRs in turn with demand misses, and a block they bring is marked until a read uses it
// (useful; late if the read found it still in flight) or it is evicted unused (useless). Their
// cost below is charged to no read, also when a read merges into one.
// Writes (stack spills in local memory) allocate without fetching (write-validate: a spill's
// refill reads only what the spill wrote). Write-back: a dirty block goes below when its line
// is evicted; write-through: every write also goes below, hit_latency after it arrives.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <queue>
#include <string>
#include <unordered_map>
#include <vector>

#include "model/mem/memory_level.h"
#include "model/mem/replacement.h"
#include "model/mem/slot_pool.h"
#include "model/mem/way_search.h"

namespace rtsim {

struct CacheConfig {
  uint64_t size_bytes = 16 * 1024;  // bytes: data capacity
  uint32_t line_bytes = 64;         // bytes: line size, a power of two
  uint32_t ways = 4;                // associativity: lines per set
  std::string replacement = "lru";  // replacement policy: lru, fifo or random
  uint32_t hit_latency = 4;         // cycles: from request to data on a hit
  uint32_t mshrs = 8;               // count: block misses in flight at once
  uint32_t sector_bytes = 0;        // bytes: fetch unit within a line; 0 = the whole line
  uint32_t merge_limit = 0;         // requests one MSHR takes besides its own; 0 = no limit
  uint32_t banks = 1;               // count: banks, lines interleaved over them (a power of two)
  uint32_t bank_ports = 0;          // lookups per bank per cycle; 0 = no limit
  double bytes_per_cycle = 0;       // bytes/cycle: data port bandwidth; 0 = no limit
  bool write_back = true;           // false: write-through (writes also go below at once)
};

// Why the config is impossible (empty if it is fine): sizes, powers of two, known policy.
std::string cache_config_problem(const CacheConfig& config);

// What a miss fetches and an MSHR tracks: the sector, or the whole line when unsectored.
inline uint32_t block_bytes(const CacheConfig& c) {
  return c.sector_bytes ? c.sector_bytes : c.line_bytes;
}

// Where a cache sits in its hierarchy (model/mem/hierarchy.h): the level whose counters of a
// ReadCharge it fills; whether it is the level above DRAM (it also counts the bytes it fetches);
// how it is filled: by its misses, or (a victim level) by the clean lines the level above evicts
// (fill), its own read misses going below without a line or an MSHR here; and whether the level
// below is such a victim level, which this one then sends its evictions to.
struct CachePlace {
  uint32_t level = 0;
  bool above_dram = true;
  bool fill_on_miss = true;
  bool victims_below = false;
};

struct CacheStats {
  uint64_t accesses = 0;            // block reads (a request spanning 2 blocks counts 2)
  uint64_t hits = 0;                // block present and ready
  uint64_t misses = 0;              // block absent: a request went below
  uint64_t cold_misses = 0;         // misses of blocks never referenced before (if tracked)
  uint64_t absent_fills = 0;        // first references served by an absent sharer (as hits)
  uint64_t mshr_merges = 0;         // block in flight: merged into its MSHR
  uint64_t merge_limit_stalls = 0;  // of them, past the merge limit: replayed after the data
  uint64_t mshr_stall_cycles = 0;   // cycles misses waited for a free MSHR
  uint64_t bank_conflicts = 0;      // line lookups that found their bank's ports taken
  uint64_t bank_stall_cycles = 0;   // cycles they waited for a port
  uint64_t port_stall_cycles = 0;   // cycles requests waited for the data port
  uint64_t evictions = 0;           // valid lines replaced
  uint64_t bytes_read = 0;          // bytes requested by reads
  uint64_t bytes_below = 0;         // bytes requested from the level below
  uint64_t writes = 0;              // block writes
  uint64_t write_misses = 0;        // of them, to an absent block: allocated without a fetch
  uint64_t write_bytes = 0;         // bytes written to this level
  uint64_t writebacks = 0;          // dirty blocks written below on eviction
  uint64_t writeback_bytes = 0;     // their bytes
  uint64_t local_reads = 0;         // reads of local memory (stack refills), as requests
  uint64_t local_misses = 0;        // their block misses
  uint64_t prefetches = 0;          // blocks a prefetch sent below
  uint64_t prefetch_redundant = 0;  // blocks a prefetch found present or in flight
  uint64_t prefetch_useful = 0;     // prefetched blocks a read used
  uint64_t prefetch_late = 0;       // of them, still in flight when read
  uint64_t prefetch_useless = 0;    // prefetched blocks evicted unused
  uint64_t victims = 0;             // clean blocks sent on eviction to the victim level below
  uint64_t victim_fills = 0;        // blocks the level above's evictions placed here
  CacheStats& operator+=(const CacheStats& o);
};

class Cache : public MemoryTarget, private ReadClient {
 public:
  // Throws std::invalid_argument for an impossible config (see cache_config_problem).
  Cache(const CacheConfig& config, MemoryTarget* below, const CachePlace& place = {});
  // Host bytes of the arrays such a cache allocates with its capacity (tags, block records, per
  // set counts), for planning memory before building one (traces/memory_plan.h).
  static uint64_t host_bytes(const CacheConfig& config);

  // Asks the host to bring what a lookup of addr reads (its set's tags, and its block in each
  // way) into its caches, for a lookup that comes later (a hint: changes nothing modelled).
  void prime(uint64_t addr) const;
  Cycle read(uint64_t addr, uint32_t bytes, Cycle at, ReadClient* client, uint64_t token,
             ReadCharge& charge) override;
  // A read over levels that all answer at once (unit tests, the cache fidelity level).
  // Throws std::logic_error if it would have to wait.
  Cycle read(uint64_t addr, uint32_t bytes, Cycle at);
  void write(uint64_t addr, uint32_t bytes, Cycle at) override;
  void prefetch(uint64_t addr, uint32_t bytes, Cycle at) override;
  // A clean line of the level above, evicted there (this is a victim level): its absent blocks
  // become valid from `at` without a fetch, through the bank and data port as a write.
  void fill(uint64_t addr, uint32_t bytes, Cycle at) override;
  // An access by a client the simulation does not drive (a scale model's absent RT units,
  // model/fidelity/l2_warming.h): its lines become most recently used and its absent blocks are
  // filled at once without going below (a write makes them dirty); victims are evicted as by a
  // miss (dirty ones written back at `at`). Counts no access, hit or miss. Returns the blocks a
  // read filled outside local memory: the fetches the client would have made from below.
  uint32_t warm(uint64_t addr, uint32_t bytes, Cycle at, bool write = false);

  // A read waiting here for a block in flight: where it comes from (none: a prefetch's miss,
  // which no read has joined), the block's address, whether its miss waits for an MSHR (else for
  // the level below), and the cycle the miss could first go below.
  struct WaitingRead {
    ReadOrigin origin;
    uint64_t addr;
    bool for_mshr;
    Cycle since;
  };
  // Every read waiting here, miss by miss, for the stall dump (slow: it walks every record).
  std::vector<WaitingRead> waiting() const;
  // Whether the block holding addr is present (in flight counts); changes nothing.
  bool contains(uint64_t addr) const;
  // Keeps a set of every block referenced, to count cold (compulsory) misses; without it
  // cold_misses stays 0. Blocks in [dense_begin, dense_end) (the BVH) are kept in a bitmap, a
  // bit test per miss; others (local memory, textures, shading reads) in bitmap pages found by
  // a hash.
  void track_cold_misses(uint64_t dense_begin = 0, uint64_t dense_end = 0);
  bool tracks_cold_misses() const { return track_cold_; }
  // For a scale model (model/fidelity/scaled_level.h): this cache stands in for a shared cache
  // of which the simulation drives only `own_share` of the clients. The first reference to a
  // block then goes below with probability own_share (decided by a hash of its address);
  // otherwise one of the absent clients fetched it, and it is a hit (absent_fills). That fetch
  // is taken to be in flight from the first reference for as long as this cache's own fetches
  // have taken on average (from a request's arrival to its data; `first_fetch_cycles` until one
  // has been answered): reads of the block until then merge into it (mshr_merges), are ready when
  // it ends and are no hits, as the requests of the full machine's clients that arrive while a
  // block's first fetch is in flight. (Without this window they all hit, and the scale model's
  // hit rate read high by about the full machine's merges on first fetches.)
  void share_first_references(double own_share, Cycle first_fetch_cycles = 0) {
    own_share_ = own_share;
    first_fetch_cycles_ = first_fetch_cycles;
    track_cold_ = true;
  }
  const CacheStats& stats() const { return stats_; }
  const CacheConfig& config() const { return config_; }
  const CachePlace& place() const { return place_; }
  uint32_t block_bytes() const { return 1u << block_shift_; }

 private:
  static constexpr uint32_t kNone = ~0u;
  static constexpr uint64_t kNoTag = ~uint64_t(0);  // the tag of an invalid line: no address has it
  struct Block {                                    // a sector of a line, or the whole line
    Cycle ready = 0;        // kPending: its miss (below) has not learnt its data's cycle
    uint32_t miss = kNone;  // that miss, while ready is kPending
    uint16_t merges = 0;    // requests merged into its last miss
    // Bits, so that a block is 16 bytes (zero in Block{} and in the cache's arrays).
    bool valid : 1;
    bool dirty : 1;
    bool prefetched : 1;  // brought by a prefetch, not read since
  };
  static_assert(sizeof(Block) == 16, "a block record is 16 bytes: four to a host cache line");
  struct Bank {
    Cycle cycle = 0;    // the cycle its next lookup can start
    uint32_t used = 0;  // ports taken in that cycle
  };
  struct Waiter {
    ReadClient* client;
    uint64_t token;
    Cycle earliest;   // its own tag check: the data cannot be ready before
    uint32_t replay;  // cycles after the data (past the merge limit: a second lookup)
    uint32_t next;    // the next waiter of the same miss (kNone: the last)
  };
  // One host cache line: an L1 answer touches it long after the miss wrote it, and a unit keeps
  // hundreds of them.
  struct alignas(64) Miss {
    uint64_t block = 0;
    Cycle send = 0;  // the cycle it may go below (after the tag check)
    // Its waiters in order: the first (the one that made the miss, unless a prefetch did) kept
    // here, as most misses have no other (client null: none yet); the others in waiters_,
    // listed from first.next to `last`.
    Waiter first{};
    uint32_t last = kNone;
    uint32_t next_waiting = kNone;  // the next miss waiting for an MSHR after it
    uint32_t way = 0;               // its line's (the set follows from the block)
    bool prefetch = false;          // made by a prefetch: its cost is charged to no read
    bool charged = false;  // the level below charged the read it has not answered: in charges_
  };
  static_assert(sizeof(Miss) == 64, "a miss record is one host cache line");
  // A read of several blocks that waits: its client, and the blocks it still waits for. Its
  // blocks' misses report to join_, which completes the read with the last of them.
  struct alignas(64) Request {  // in one host cache line, as a Miss
    ReadClient* client = nullptr;
    uint64_t token = 0;
    uint32_t blocks = 0;
    Cycle ready = 0;
    ReadCharge charge;
  };
  struct Join : ReadClient {
    explicit Join(Cache& cache) : cache(cache) {}
    void read_done(uint64_t request, Cycle ready, const ReadCharge& charge) override {
      cache.complete_part(uint32_t(request), ready, charge);
    }
    ReadOrigin origin(uint64_t request) const override {
      const Request& r = cache.requests_[request];
      return r.client->origin(r.token);
    }
    Cache& cache;
  };
  struct Caller {  // the read being served (client null: a prefetch, nobody waits); a read of
                   // several blocks gets a Request to wait
    ReadClient* client;
    uint64_t token;
    bool several_blocks;
    uint32_t request;
  };

  // The cycle a lookup of `line` moving `bytes` starts: its bank's port and the data port free
  // (called only if admits_).
  Cycle admit(uint64_t line, uint64_t bytes, Cycle at);
  // Calls f(line, begin, stop) for each line [addr, addr + bytes) touches, with the part of
  // the range inside it.
  template <class F>
  void for_each_line(uint64_t addr, uint32_t bytes, F f) const {
    uint64_t end = addr + std::max<uint32_t>(bytes, 1);
    for (uint64_t line = addr >> line_shift_; line <= (end - 1) >> line_shift_; ++line)
      f(line, std::max(addr, line << line_shift_), std::min(end, (line + 1) << line_shift_));
  }
  struct Place {  // a line's set, and its way (kNone: absent)
    uint32_t set, way;
  };
  // Where `line` is; if present, touched once for all of a read's blocks in it (LRU compares
  // only the order of lines' last uses).
  Place look_up(uint64_t line);
  // Where `line` is, given a way if absent (a victim evicted at `at`), else touched: a line that
  // arrives without a fetch (warm, fill).
  Place place(uint64_t line, Cycle at);
  // A block's ready cycle, or kPending once the caller waits for it; an absent line is given a
  // way (p.way).
  Cycle read_block(uint64_t block, Place& p, Cycle at, Caller& caller, ReadCharge& charge);
  struct Absent {
    Cycle ready;   // read_block's answer
    uint32_t way;  // the line's way, given to it if it had none
  };
  // read_block's path for a block absent from its line (way: the line's, or kNone): gives an
  // absent line its way, then the miss (kept out of line, so the hit path stays short).
  [[gnu::noinline]] Absent read_absent(uint64_t block, uint32_t set, uint32_t way, Cycle at,
                                       Caller& caller, ReadCharge& charge);
  // A victim level's read miss: sent below for the reader, after the tag check, holding no line
  // or MSHR here.
  Cycle read_through(uint64_t block, Cycle at, Caller& caller, ReadCharge& charge);
  void write_block(uint64_t block, Cycle at);
  void used_prefetch(Block& b, Cycle at);  // a read's first use of a prefetched block
  // Counts a merge into the in-flight block; returns its replay cycles (past the merge limit).
  uint32_t merge(Block& b);
  // A fetch's latency, from its request's arrival (before the tag check) to its data, summed
  // for the absent fills' window (share_first_references; only a scale model's cache needs it).
  void note_fetch(const Miss& m, Cycle ready) {
    if (own_share_ == 1.0) return;
    fetch_cycles_ += ready - (m.send - config_.hit_latency);
    fetches_++;
  }
  // The mean of those latencies so far (first_fetch_cycles_ until one is known).
  Cycle mean_fetch_cycles() const {
    return fetches_ ? fetch_cycles_ / fetches_ : first_fetch_cycles_;
  }
  void wait_for(uint32_t miss, Caller& caller, Cycle earliest, uint32_t replay);
  void add_waiter(uint32_t miss, const Waiter& waiter);
  [[gnu::always_inline]] Cycle miss(uint64_t block, uint32_t set, uint32_t way, Cycle at,
                                    Caller& caller, ReadCharge& charge);
  // Sends a miss below at `at` (its MSHR taken); the below's answer: a cycle, or kPending. What
  // the level below charged is in `below` if it answered, else kept for read_done.
  Cycle issue(uint32_t miss, Cycle at, ReadCharge& below);
  void read_done(uint64_t miss, Cycle ready, const ReadCharge& charge) override;
  void prime_done(uint64_t miss) const override { __builtin_prefetch(&misses_[miss], 0, kHostL2); }
  // The first waiter's origin (none for a prefetch's miss).
  ReadOrigin origin(uint64_t miss) const override;
  void complete_part(uint32_t request, Cycle ready, const ReadCharge& charge);
  uint32_t find(uint32_t set, uint64_t tag) const;  // the way holding tag, or kNone
  WaySearch find_way_ = way_search();
  // Gives a way of the set to `tag`, evicting a victim (its dirty blocks written back at `at`).
  uint32_t allocate(uint32_t set, uint64_t tag, Cycle at);
  size_t block_index(uint32_t set, uint32_t way, uint64_t block) const {
    return ((size_t(set) * config_.ways + way) << sector_shift_) + (block & sector_mask_);
  }
  Block& block_at(uint32_t set, uint32_t way, uint64_t block) {
    return blocks_[block_index(set, way, block)];
  }

  // Set and tag of a line number: shifts and masks for a power-of-two set count (divisions
  // are slow on the hot path), divisions otherwise.
  uint32_t set_of(uint64_t line) const {
    return uint32_t(set_shift_ ? line & (sets_ - 1) : line % sets_);
  }
  uint64_t tag_of(uint64_t line) const { return set_shift_ ? line >> set_shift_ : line / sets_; }

  CacheConfig config_;
  MemoryTarget* below_;
  CachePlace place_;
  uint32_t sets_;
  uint32_t set_shift_ = 0;     // log2(sets_) if sets_ is a power of two above 1, else 0
  uint32_t line_shift_ = 0;    // log2(line_bytes)
  uint32_t block_shift_ = 0;   // log2(bytes of a block: the sector, or the line)
  uint32_t sector_shift_ = 0;  // log2(blocks per line)
  uint64_t sector_mask_ = 0;
  bool admits_ = false;           // banks or the data port limit lookups
  std::vector<uint64_t> tags_;    // of the lines, sets_ x ways, set-major
  std::vector<uint32_t> filled_;  // per set: ways holding a line
  std::vector<Block> blocks_;     // tags_ x blocks per line
  std::vector<Bank> banks_;
  double port_free_ = 0;  // cycle (fractional) the data port is free from
  ReplacementPolicy policy_;
  // The cycles the MSHRs not holding a miss are free from, earliest first. An MSHR whose miss
  // has not learnt its data's cycle is in none of them.
  std::priority_queue<Cycle, std::vector<Cycle>, std::greater<Cycle>> free_mshrs_;
  std::vector<Miss> misses_;
  // What the level below charged a miss it answers later (Miss::charged; only a level that
  // counts its accesses at once, another Cache, does), by miss.
  std::vector<ReadCharge> charges_;
  std::vector<Waiter> waiters_;  // the waiters of all misses, in lists through Waiter::next
  std::vector<uint32_t> free_waiters_;
  std::vector<uint32_t> free_misses_;
  // Misses for which every MSHR's end was unknown, first come first: a list through
  // Miss::next_waiting from waiting_first_ to waiting_last_ (kNone: empty).
  uint32_t waiting_first_ = kNone, waiting_last_ = kNone;
  void add_waiting(uint32_t miss);
  uint32_t take_waiting();
  std::vector<Request> requests_;
  std::vector<uint32_t> free_requests_;
  Join join_{*this};
  // Marks a block referenced; true the first time.
  static bool mark(uint64_t* bits, uint64_t i) {
    uint64_t bit = uint64_t(1) << (i & 63);
    bool first = !(bits[i >> 6] & bit);
    bits[i >> 6] |= bit;
    return first;
  }
  bool first_reference(uint64_t block) {
    uint64_t i = block - dense_first_;
    if (i < dense_blocks_) return mark(dense_held_.data(), i);
    return mark(held_pages_[block >> kPageShift].data(), block & ((1u << kPageShift) - 1));
  }
  std::vector<uint64_t> dense_held_;  // a bit per block of the dense range
  uint64_t dense_first_ = 0, dense_blocks_ = 0;
  // The other blocks ever referenced, a bit each in pages of 4096 blocks (streams of shading
  // reads and stack spills touch whole pages, so a page costs one allocation, not 4096).
  static constexpr uint32_t kPageShift = 12;
  std::unordered_map<uint64_t, std::array<uint64_t, (1u << kPageShift) / 64>> held_pages_;
  bool track_cold_ = false;
  double own_share_ = 1.0;
  uint64_t fetch_cycles_ = 0, fetches_ = 0;  // see note_fetch
  Cycle first_fetch_cycles_ = 0;
  CacheStats stats_;
};

}  // namespace rtsim
