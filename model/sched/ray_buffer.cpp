#include "model/sched/ray_buffer.h"

#include <algorithm>
#include <stdexcept>

namespace rtsim {

const char* ray_buffer_place_name(RayBufferPlace place) {
  return place == RayBufferPlace::Memory ? "memory" : "sram";
}

const char* ray_buffer_overflow_name(RayBufferOverflow overflow) {
  return overflow == RayBufferOverflow::Spill ? "spill" : "hold";
}

std::string ray_buffer_config_problem(const RayBufferConfig& c) {
  if (c.banks == 0 || c.banks > 1024) return "buffer_banks must be 1..1024";
  return {};
}

uint32_t ray_state_bytes(const StackConfig& stack, bool two_level) {
  return 32 + 16 + 8 + (two_level ? 40 : 0) + stack.entries * stack.entry_bytes;
}

uint64_t ray_state_address(uint32_t context, uint32_t state_bytes) {
  // Above the stack spill regions of the most contexts a pool may have (2^24).
  constexpr uint64_t kStateBase = HardwareStack::kSpillBase + (uint64_t(1) << 40);
  uint64_t stride = (uint64_t(state_bytes) + 63) / 64 * 64;
  return kStateBase + context * stride;
}

uint64_t ray_buffer_capacity(const RayBufferConfig& c, uint32_t state_bytes, uint32_t max_rays) {
  if (c.place == RayBufferPlace::Memory) return 0;
  return c.bytes == 0 ? max_rays : c.bytes / state_bytes;
}

RayBuffer::RayBuffer(const RayBufferConfig& config, uint32_t state_bytes, uint32_t max_rays)
    : config_(config),
      state_bytes_(state_bytes),
      capacity_(ray_buffer_capacity(config, state_bytes, max_rays)),
      ports_(config.bytes_per_cycle == 0 ? 0 : config.banks, TestUnitPool({1, 1, 1})) {
  std::string problem = ray_buffer_config_problem(config);
  if (!problem.empty()) throw std::invalid_argument(problem);
}

bool RayBuffer::holds_back() const {
  return config_.place == RayBufferPlace::Sram && config_.overflow == RayBufferOverflow::Hold &&
         in_sram_ >= capacity_;
}

bool RayBuffer::admits_fresh() {
  bool held = holds_back();
  stats_.held += held;
  return !held;
}

bool RayBuffer::accepts() {
  bool held = holds_back();
  stats_.refused += held;
  return !held;
}

Cycle RayBuffer::transfer(const RayContext& ray, Cycle now) {
  stats_.sram_bytes += state_bytes_;
  if (ports_.empty()) return now + config_.latency;
  // One "test" per port cycle; the pool reports the cycle after the last.
  uint32_t cycles = (state_bytes_ + config_.bytes_per_cycle - 1) / config_.bytes_per_cycle;
  return ports_[ray.id % config_.banks].reserve(now, cycles) - 1 + config_.latency;
}

RayBufferStats RayBuffer::stats() const {
  RayBufferStats s = stats_;
  for (const TestUnitPool& port : ports_) {
    s.port_cycles += port.stats().issues;
    s.port_waits += port.stats().stall_cycles;
  }
  return s;
}

Cycle RayBuffer::store(RayContext& ray, Cycle now) {
  ray.state_in_memory = in_sram_ >= capacity_;
  if (ray.state_in_memory) {
    stats_.memory_writes++;
    stats_.memory_bytes += state_bytes_;
    return now;
  }
  in_sram_++;
  stats_.max_in_sram = std::max(stats_.max_in_sram, in_sram_);
  stats_.sram_writes++;
  return transfer(ray, now);
}

Cycle RayBuffer::load(RayContext& ray, Cycle now) {
  if (ray.state_in_memory) {
    stats_.memory_reads++;
    stats_.memory_bytes += state_bytes_;
    return now;
  }
  in_sram_--;
  stats_.sram_reads++;
  return transfer(ray, now);
}

}  // namespace rtsim
