#include "model/mem/stack_distance.h"

#include <algorithm>
#include <stdexcept>

#include "model/mem/slice_hash.h"

namespace rtsim {

namespace {

bool power_of_two(uint64_t v) {
  return v && !(v & (v - 1));
}

}  // namespace

LruStackSets::LruStackSets(const L2Sets& sets, uint32_t max_ways)
    : sets_(sets), max_ways_(max_ways) {
  if (max_ways < 1 || max_ways > kMaxWays)
    throw std::invalid_argument("stack distances: max_ways must be 1 to 254");
  if (!power_of_two(sets.line_bytes) || !power_of_two(sets.block_bytes) ||
      sets.block_bytes > sets.line_bytes || sets.line_bytes / sets.block_bytes > kMaxBlocksPerLine)
    throw std::invalid_argument(
        "stack distances: line and block bytes must be powers of two, at most 16 blocks a line");
  if (sets.slices < 1 || sets.sets_per_slice < 1)
    throw std::invalid_argument("stack distances: at least one slice and one set");
  line_shift_ = uint32_t(__builtin_ctz(sets.line_bytes));
  block_shift_ = uint32_t(__builtin_ctz(sets.block_bytes));
  blocks_per_line_ = sets.line_bytes / sets.block_bytes;
  uint64_t set_count = uint64_t(sets.slices) * sets.sets_per_slice;
  stacks_.resize(set_count * max_ways);
  filled_.assign(set_count, 0);
  read_distance_.assign(max_ways + 1, 0);
  writeback_distance_.assign(max_ways + 1, 0);
}

uint64_t LruStackSets::host_bytes(const L2Sets& sets, uint32_t max_ways) {
  uint64_t set_count = uint64_t(sets.slices) * sets.sets_per_slice;
  return set_count * (max_ways * sizeof(Entry) + sizeof(uint8_t));
}

LruStackSets::Entry LruStackSets::fresh(uint64_t line) const {
  Entry e;
  e.line = line;
  e.seen.fill(uint8_t(max_ways_));
  e.dirty.fill(kClean);
  return e;
}

void LruStackSets::drop(const Entry& entry) {
  for (uint32_t b = 0; b < blocks_per_line_; ++b)
    if (entry.dirty[b] != kClean) writeback_distance_[max_ways_]++;
}

void LruStackSets::reference(uint64_t addr, bool write) {
  uint64_t line = addr >> line_shift_;
  uint32_t block = uint32_t((addr >> block_shift_) & (blocks_per_line_ - 1));
  uint64_t set =
      slice_of_line(line, sets_.slices) * sets_.sets_per_slice + line % sets_.sets_per_slice;
  Entry* stack = &stacks_[set * max_ways_];
  uint32_t held = filled_[set], depth = 0;
  while (depth < held && stack[depth].line != line) ++depth;
  bool found = depth < held;
  auto distance = uint8_t(found ? depth : max_ways_);
  Entry e = found ? stack[depth] : fresh(line);
  if (!found && held == max_ways_) {  // evicted at every depth: the bottom line leaves
    drop(stack[held - 1]);
    depth = held - 1;
  } else if (!found) {
    filled_[set] = uint8_t(held + 1);
  }
  std::copy_backward(stack, stack + depth, stack + depth + 1);  // the others move down one
  for (uint32_t b = 0; b < blocks_per_line_; ++b) {
    e.seen[b] = std::max(e.seen[b], distance);
    if (e.dirty[b] != kClean) e.dirty[b] = std::max(e.dirty[b], distance);
  }
  if (write) {
    writes_++;
    if (e.dirty[block] != kClean) writeback_distance_[e.dirty[block]]++;
    e.dirty[block] = 0;
  } else {
    reads_++;
    read_distance_[e.seen[block]]++;
  }
  e.seen[block] = 0;
  stack[0] = e;
}

void LruStackSets::finish() {
  for (size_t set = 0; set < filled_.size(); ++set)
    for (uint32_t depth = 0; depth < filled_[set]; ++depth) {
      Entry& e = stacks_[set * max_ways_ + depth];
      for (uint32_t b = 0; b < blocks_per_line_; ++b) {
        if (e.dirty[b] == kClean) continue;
        writeback_distance_[std::max<uint32_t>(e.dirty[b], depth)]++;
        e.dirty[b] = kClean;
      }
    }
}

uint64_t LruStackSets::at_least(const std::vector<uint64_t>& histogram, uint32_t ways) {
  uint64_t sum = 0;
  for (size_t d = std::min<size_t>(ways, histogram.size()); d < histogram.size(); ++d)
    sum += histogram[d];
  return sum;
}

}  // namespace rtsim
