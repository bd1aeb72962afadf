// A cache set's tag search: the way whose tag equals the one looked for. Every way is compared,
// without a branch on the tags (a set holds a line once): the way a hit is in is random, and a
// mispredicted early exit costs the host more than comparing the rest. On hosts with AVX2 four
// tags a compare (integer compares, so the same answer on every host); it is the caches' most
// executed loop (a 16-way L2 slice compares 16 tags a lookup).
#pragma once

#include <cstdint>

namespace rtsim {

// The index of the first of `count` tags equal to `tag`, or ~0u if none is.
using WaySearch = uint32_t (*)(const uint64_t* tags, uint32_t count, uint64_t tag);

uint32_t find_way_portable(const uint64_t* tags, uint32_t count, uint64_t tag);
// Null where the host (or the build's target) lacks AVX2.
WaySearch find_way_avx2();
// The fastest search this host runs.
WaySearch way_search();

}  // namespace rtsim
