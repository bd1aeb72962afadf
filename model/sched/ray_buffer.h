// The ray buffer of the treelet queues: where a postponed ray's state (the ray, its hit record
// and its on-chip stack entries) waits for its treelet's turn. Aila & Karras (HPG 2010) name
// moving it the foremost auxiliary cost of treelet queues: postponing a ray writes its state,
// resuming it reads it back.
// Place: a dedicated SRAM (banks, each with a port of bytes_per_cycle, and an access latency), or
// memory, where the state goes through the units' L1s to the L2 and DRAM like any data. While
// the SRAM is full (overflow "hold"), fresh rays are held back and a ray about to be postponed
// keeps traversing in its unit, as at a full queue; with overflow "spill" further states go to
// memory instead.
// The buffer times the SRAM itself; a state in memory is written and read by the unit
// (RayContext::state_in_memory tells it), through its L1, at ray_state_address.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "model/sched/hardware_stack.h"
#include "model/sched/ray_context.h"
#include "model/sched/test_unit_pool.h"

namespace rtsim {

enum class RayBufferPlace : uint8_t { Sram, Memory };
enum class RayBufferOverflow : uint8_t { Hold, Spill };

struct RayBufferConfig {
  RayBufferPlace place = RayBufferPlace::Sram;
  uint64_t bytes = 0;  // bytes: SRAM capacity; 0: room for every ray of max_rays
  RayBufferOverflow overflow = RayBufferOverflow::Hold;
  uint32_t banks = 1;            // SRAM banks; a ray context's state lives in bank id % banks
  uint32_t bytes_per_cycle = 0;  // bytes/cycle: each bank's port, reads and writes; 0: no limit
  uint32_t latency = 0;          // cycles: SRAM access, after the transfer's last port cycle
};

const char* ray_buffer_place_name(RayBufferPlace place);           // sram, memory
const char* ray_buffer_overflow_name(RayBufferOverflow overflow);  // hold, spill
std::string ray_buffer_config_problem(const RayBufferConfig& config);

// States the SRAM holds: none in memory; max_rays for bytes = 0; else bytes / state_bytes.
uint64_t ray_buffer_capacity(const RayBufferConfig& config, uint32_t state_bytes,
                             uint32_t max_rays);
// Bytes of one ray's state: the ray (origin, direction, t range: 32), its hit record (t,
// triangle, barycentrics: 16), its id and treelet (8), and its on-chip stack entries; two
// levels add the world-space ray kept while in an instance (32), its instance and the closest
// hit when it entered (8).
uint32_t ray_state_bytes(const StackConfig& stack, bool two_level = false);
// Where a ray context's state lives in memory: local memory above every stack spill region.
uint64_t ray_state_address(uint32_t context, uint32_t state_bytes);

struct RayBufferStats {
  uint64_t sram_writes = 0, sram_reads = 0, sram_bytes = 0;        // states into and out of SRAM
  uint64_t memory_writes = 0, memory_reads = 0, memory_bytes = 0;  // states to and from memory
  uint64_t held = 0;         // requests for fresh rays refused because the SRAM was full
  uint64_t refused = 0;      // postponements refused because the SRAM was full
  uint64_t max_in_sram = 0;  // most states in SRAM at once
  uint64_t port_cycles = 0;  // cycles of bank ports busy, all banks
  uint64_t port_waits = 0;   // cycles transfers waited for a busy port
};

class RayBuffer {
 public:
  RayBuffer(const RayBufferConfig& config, uint32_t state_bytes, uint32_t max_rays);

  uint32_t state_bytes() const { return state_bytes_; }
  uint64_t capacity() const { return capacity_; }  // states the SRAM holds
  // Whether fresh rays may enter (counts a refusal).
  bool admits_fresh();
  // Whether a postponed ray's state has a place (counts a refusal).
  bool accepts();
  // The ray is queued at `now` (after accepts()); returns the cycle its state is stored. A state
  // bound for memory is marked for the unit to write: the cycle is `now`.
  Cycle store(RayContext& ray, Cycle now);
  // The ray leaves its queue at `now`; returns the cycle its state is back from SRAM (`now` for a
  // state in memory, which the unit reads).
  Cycle load(RayContext& ray, Cycle now);
  RayBufferStats stats() const;

 private:
  bool holds_back() const;  // the SRAM is full and overflow is "hold"
  Cycle transfer(const RayContext& ray, Cycle now);

  RayBufferConfig config_;
  uint32_t state_bytes_;
  uint64_t capacity_;
  uint64_t in_sram_ = 0;
  // Per bank, its port: a transfer of n bytes takes ceil(n / bytes_per_cycle) of its cycles, the
  // first free ones at or after the request (requests may come in any cycle order, as units
  // run ahead of each other); the data is there `latency` cycles after the last. None: no limit.
  std::vector<TestUnitPool> ports_;
  RayBufferStats stats_;
};

}  // namespace rtsim
