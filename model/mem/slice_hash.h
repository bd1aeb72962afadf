// Which slice of the shared L2 a line lives in: the slices are address-hashed (Fibonacci hashing
// of the line number), so consecutive lines spread over them; within its slice a line's set is
// its line number modulo the slice's set count (model/mem/cache.h). The cycle model's L2
// (model/sc/shared_levels_module.h) and the cache curves (model/fidelity/cache_curve.h) use it.
#pragma once

#include <cstdint>

namespace rtsim {

inline uint32_t slice_of_line(uint64_t line, uint32_t slices) {
  if (slices <= 1) return 0;
  uint64_t h = line * 0x9e3779b97f4a7c15ull;
  return uint32_t((h >> 32) % slices);
}

}  // namespace rtsim
