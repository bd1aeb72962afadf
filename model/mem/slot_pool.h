// Records in a vector reused through a free list of their indices: the cache's misses, waiters
// and requests, the shared L2's reads waiting for their slice or for DRAM. An index stays valid
// until it is given back; the vector may move when a slot is taken.
#pragma once

#include <cstdint>
#include <vector>

namespace rtsim {

// A free slot of `pool` (a new one if none is free); its record keeps its old value.
template <class T>
uint32_t take_slot(std::vector<T>& pool, std::vector<uint32_t>& free) {
  if (free.empty()) {
    pool.emplace_back();
    return uint32_t(pool.size() - 1);
  }
  uint32_t id = free.back();
  free.pop_back();
  return id;
}

}  // namespace rtsim
