// The contract between levels of the memory hierarchy, in plain C++ (no SystemC).
// A level answers a read of `bytes` at `addr` issued at cycle `now` with the cycle the data
// is ready. Calls must arrive in non-decreasing `now` order per level (each level keeps
// reservations of its own resources: MSHRs, a data bus); a call may change only the level's
// own state and stats and those of the levels below it.
#pragma once

#include <cstdint>

namespace rtsim {

using Cycle = uint64_t;

class MemoryLevel {
public:
  virtual ~MemoryLevel() = default;
  virtual Cycle read(uint64_t addr, uint32_t bytes, Cycle now) = 0;
};

}  // namespace rtsim
