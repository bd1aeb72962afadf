// Records in a vector reused through a free list of their indices: the cache's misses, waiters
// and requests, the shared L2's reads waiting for their slice or for DRAM. An index stays valid
// until it is given back; the vector may move when a slot is taken.
#pragma once

#include <cstdint>
#include <vector>

namespace rtsim {

// The slot take_slot gives next, taking nothing (a record's id known before it is needed).
template <class T>
uint32_t next_slot(const std::vector<T>& pool, const std::vector<uint32_t>& free) {
  return free.empty() ? uint32_t(pool.size()) : free.back();
}

// A free slot of `pool` (a new one if none is free); its record keeps its old value.
template <class T>
uint32_t take_slot(std::vector<T>& pool, std::vector<uint32_t>& free) {
  uint32_t id = next_slot(pool, free);
  if (free.empty())
    pool.emplace_back();
  else
    free.pop_back();
  return id;
}

}  // namespace rtsim
