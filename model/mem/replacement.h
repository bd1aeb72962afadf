// Cache replacement policies behind one interface; implementations in impl/.
// A policy sees only (set, way) events; it may change only its own per-set state.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace rtsim {

class ReplacementPolicy {
public:
  virtual ~ReplacementPolicy() = default;
  // A hit on (set, way).
  virtual void touch(uint32_t set, uint32_t way) = 0;
  // A line was just installed in (set, way).
  virtual void insert(uint32_t set, uint32_t way) = 0;
  // The way to evict from a full set.
  virtual uint32_t victim(uint32_t set) = 0;
};

// "lru", "fifo" or "random" (seeded, deterministic); nullptr for an unknown name.
std::unique_ptr<ReplacementPolicy> make_replacement_policy(const std::string& name, uint32_t sets,
                                                           uint32_t ways, uint64_t seed = 1);
std::vector<std::string> replacement_policy_names();

}  // namespace rtsim
