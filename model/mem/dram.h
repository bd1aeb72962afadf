// DRAM behind the last cache level: one data bus of fixed peak bandwidth, a fixed access
// latency, and a bounded request queue. Transfers move whole bursts (burst_bytes).
// Timing: a request takes the bus when it is free (first come, first served) for
// bytes / bytes_per_cycle cycles, and its data is ready `latency` cycles after its transfer
// ends. Bandwidth is never exceeded: transfers never overlap. When queue_depth requests are
// already waiting for the bus, a new request waits until one of them starts (back-pressure,
// counted as queue stall cycles). Writes take the bus like reads; nobody waits for them.
// Calls come in non-decreasing `now` (the shared L2's module serves requests in simulated-time
// order), so first come is first dated. Row buffers and banks are not modelled; bind another
// TLM memory model in sc/ for that.
#pragma once

#include <cstdint>
#include <functional>
#include <queue>
#include <string>
#include <vector>

#include "model/mem/memory_level.h"

namespace rtsim {

struct DramConfig {
  double bytes_per_cycle = 32.0;  // bytes/cycle: peak bandwidth of the data bus
  uint32_t latency = 200;         // cycles: from the end of a transfer to data ready
  uint32_t queue_depth = 64;      // count: requests that may wait for the bus
  uint32_t burst_bytes = 32;      // bytes: the smallest transfer, a power of two
};

std::string dram_config_problem(const DramConfig& config);

struct DramStats {
  uint64_t requests = 0;
  uint64_t bytes = 0;                 // reads and writes, in whole bursts
  uint64_t write_bytes = 0;           // of them written
  double busy_cycles = 0;             // cycles the data bus was transferring
  uint64_t queue_stall_cycles = 0;    // cycles requests waited for room in the queue
  uint64_t total_latency_cycles = 0;  // sum over requests of ready - arrival
  Cycle last_ready = 0;               // cycle the last transfer's data was ready
};

class Dram {
 public:
  explicit Dram(const DramConfig& config);  // throws std::invalid_argument if impossible
  Cycle read(uint64_t addr, uint32_t bytes, Cycle now);  // the data's ready cycle
  void write(uint64_t addr, uint32_t bytes, Cycle now);
  const DramStats& stats() const { return stats_; }
  const DramConfig& config() const { return config_; }

 private:
  DramConfig config_;
  double bus_free_ = 0;  // cycle (fractional) the bus finishes its last reserved transfer
  std::priority_queue<double, std::vector<double>, std::greater<double>> waiting_;  // starts
  DramStats stats_;
};

// A Dram as the level below a cache that answers every read at once (unit tests, the cache
// fidelity level).
class DramTarget : public MemoryTarget {
 public:
  explicit DramTarget(Dram& dram) : dram_(dram) {}
  Cycle read(uint64_t addr, uint32_t bytes, Cycle at, ReadClient*, uint64_t, ReadCharge&) override {
    return dram_.read(addr, bytes, at);
  }
  void write(uint64_t addr, uint32_t bytes, Cycle at) override { dram_.write(addr, bytes, at); }

 private:
  Dram& dram_;
};

}  // namespace rtsim
