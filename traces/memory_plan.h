// Memory planning: a step that allocates in proportion to its input (a built-in scene's
// triangles, a trace's pixels) first estimates what it needs and refuses with the estimate
// (InputError, exit 2) when that exceeds the memory available, instead of ending in bad_alloc
// or the OOM killer hours later. The estimates are measured peaks per unit (see the constants'
// users) rounded up; they err on the generous side of the real need by up to a fifth.
#pragma once

#include <cstdint>
#include <string>

namespace rtsim {

// Bytes this process can plan for: the address space left under `ulimit -v` (RLIMIT_AS less
// what the process maps already), or less: the environment's RTSIM_MAX_MEMORY (a size:
// traces/byte_size.h, 4G) if set, else the smaller of /proc/meminfo's MemAvailable and the
// cgroup's memory.max.
uint64_t available_memory_bytes();

// Throws InputError naming source if `bytes` exceeds available_memory_bytes():
// "SOURCE: WHAT needs about N GB of memory, more than the M GB available; ADVICE".
void require_memory(uint64_t bytes, const std::string& source, const std::string& what,
                    const std::string& advice);

}  // namespace rtsim
