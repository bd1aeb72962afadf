// LRU stack distances per set, for the shared L2 as the cycle model builds it: Mattson's stack
// algorithm (Mattson, Gecsei, Slutz and Traiger, "Evaluation techniques for storage
// hierarchies", IBM Systems Journal 9(2), 1970) applied to each set, as Hill and Smith do for
// set-associative caches ("Evaluating associativity in CPU caches", IEEE ToC 38(12), 1989).
// Lines go to slices by slice_of_line and to sets by line modulo the sets per slice, as in
// model/sc/shared_levels_module.h. By the inclusion property a W-way LRU set holds the W most
// recently referenced lines of its set, so one pass over a reference stream gives the misses
// and write-backs of every associativity up to max_ways at this set count. Each set keeps its
// lines in recency order, max_ways deep: a reference costs the depth it finds its line at.
//
// What the cycle model's cache (model/mem/cache.h) does, counted the same way, with no timing:
// - sectors: a read fetches only its block; it hits if its line stayed in the cache since that
//   block's last reference, i.e. if every reference to the line since then found the line less
//   than W deep. A read's distance is therefore the largest line distance since its block was
//   last referenced (never referenced: infinite), and it misses in a W-way cache iff >= W;
// - writes allocate without fetching (write-validate) and make their block valid and dirty;
//   a dirty block is written back when its line is evicted. A write's write-back distance is the
//   largest line distance until its block's next write (or, for the last write, until the end,
//   with the line's depth at the end): a W-way cache writes it back iff that is >= W.
// Distances of max_ways or more are kept as max_ways ("at least").
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace rtsim {

// Where the lines of the L2 live: slices and sets per slice; blocks are sectors of lines.
struct L2Sets {
  uint32_t line_bytes = 128;    // bytes: line size, a power of two
  uint32_t block_bytes = 32;    // bytes: what a miss fetches (a sector, or the line)
  uint32_t slices = 1;          // count: address-hashed slices
  uint64_t sets_per_slice = 1;  // count: sets in each slice
};

class LruStackSets {
 public:
  static constexpr uint32_t kMaxWays = 254;
  static constexpr uint32_t kMaxBlocksPerLine = 16;
  // Throws std::invalid_argument for max_ways outside 1..kMaxWays or a line of more blocks.
  LruStackSets(const L2Sets& sets, uint32_t max_ways);
  // Host bytes of the stacks such an object allocates, for planning memory before building one.
  static uint64_t host_bytes(const L2Sets& sets, uint32_t max_ways);

  // One reference to the block holding addr (a read, or a write of the whole block).
  void reference(uint64_t addr, bool write);
  // The end of the stream: the dirty blocks still held are written back in caches too small to
  // hold their lines to the end. Call once, before writebacks().
  void finish();

  uint64_t reads() const { return reads_; }
  uint64_t writes() const { return writes_; }
  // For an LRU cache of these sets and `ways` ways (1..max_ways):
  uint64_t read_misses(uint32_t ways) const { return at_least(read_distance_, ways); }
  uint64_t writebacks(uint32_t ways) const { return at_least(writeback_distance_, ways); }
  // Histograms: entry d counts the reads (writes) of distance d; the last, max_ways or more.
  const std::vector<uint64_t>& read_distances() const { return read_distance_; }
  const std::vector<uint64_t>& writeback_distances() const { return writeback_distance_; }

 private:
  struct Entry {
    uint64_t line = 0;
    // Per block: the largest line distance since its last reference (seen) and, while it
    // holds a write not yet counted, since that write (dirty; kClean when none).
    std::array<uint8_t, kMaxBlocksPerLine> seen{};
    std::array<uint8_t, kMaxBlocksPerLine> dirty{};
  };
  static constexpr uint8_t kClean = 0xff;
  static uint64_t at_least(const std::vector<uint64_t>& histogram, uint32_t ways);
  Entry fresh(uint64_t line) const;  // a line not in its set's stack: every block unseen
  void drop(const Entry& entry);     // a line pushed out of the stack: evicted at every depth

  L2Sets sets_;
  uint32_t max_ways_, line_shift_, block_shift_, blocks_per_line_;
  std::vector<Entry> stacks_;    // per set, max_ways entries, most recent first
  std::vector<uint8_t> filled_;  // per set: entries in use
  std::vector<uint64_t> read_distance_, writeback_distance_;
  uint64_t reads_ = 0, writes_ = 0;
};

}  // namespace rtsim
