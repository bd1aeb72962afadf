#include "model/mem/dram.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rtsim {

std::string dram_config_problem(const DramConfig& c) {
  if (!(c.bytes_per_cycle > 0) || !std::isfinite(c.bytes_per_cycle))
    return "bytes_per_cycle must be positive";
  if (c.queue_depth == 0) return "queue_depth must be at least 1";
  if (c.burst_bytes == 0 || (c.burst_bytes & (c.burst_bytes - 1)) != 0)
    return "burst_bytes must be a power of two";
  return {};
}

Dram::Dram(const DramConfig& config) : config_(config) {
  std::string problem = dram_config_problem(config);
  if (!problem.empty()) throw std::invalid_argument(problem);
}

Cycle Dram::read(uint64_t addr, uint32_t requested, Cycle now) {
  // Whole bursts move: the bursts that [addr, addr + requested) touches.
  uint64_t burst = config_.burst_bytes;
  uint64_t begin = addr & ~(burst - 1);
  uint64_t end = (addr + std::max<uint32_t>(requested, 1) + burst - 1) & ~(burst - 1);
  uint64_t bytes = end - begin;
  // Requests whose transfer has started have left the queue.
  while (!waiting_.empty() && waiting_.top() <= double(now)) waiting_.pop();
  double arrival = double(now);
  if (waiting_.size() >= config_.queue_depth) {
    arrival = waiting_.top();
    waiting_.pop();
    stats_.queue_stall_cycles += Cycle(std::ceil(arrival)) - now;
  }
  double start = std::max(arrival, bus_free_);
  double transfer = double(bytes) / config_.bytes_per_cycle;
  bus_free_ = start + transfer;
  if (start > arrival) waiting_.push(start);

  Cycle ready = Cycle(std::ceil(bus_free_)) + config_.latency;
  stats_.requests++;
  stats_.bytes += bytes;
  stats_.busy_cycles += transfer;
  stats_.total_latency_cycles += ready - now;
  stats_.last_ready = std::max(stats_.last_ready, ready);
  return ready;
}

void Dram::write(uint64_t addr, uint32_t bytes, Cycle now) {
  uint64_t before = stats_.bytes;
  read(addr, bytes, now);
  stats_.write_bytes += stats_.bytes - before;
}

}  // namespace rtsim
