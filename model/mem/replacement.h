// Cache replacement policies: LRU and FIFO evict the way with the oldest stamp and differ in
// when a stamp is set (LRU on every touch, FIFO only on insert); random is a seeded xorshift,
// so runs are repeatable. A policy sees only (set, way) events. One concrete class, so the
// cache's hot path calls it without indirection.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rtsim {

class ReplacementPolicy {
 public:
  enum class Kind : uint8_t { Lru, Fifo, Random };
  ReplacementPolicy() = default;  // of no set: for a cache to assign one once it knows its sets
  ReplacementPolicy(Kind kind, uint32_t sets, uint32_t ways, uint64_t seed);

  // A hit on (set, way).
  void touch(uint32_t set, uint32_t way) {
    if (kind_ == Kind::Lru) stamps_[size_t(set) * ways_ + way] = ++clock_;
  }
  // A line was just installed in (set, way).
  void insert(uint32_t set, uint32_t way) {
    if (kind_ != Kind::Random) stamps_[size_t(set) * ways_ + way] = ++clock_;
  }
  // The way to evict from a full set: the first with the oldest stamp.
  uint32_t victim(uint32_t set) {
    if (kind_ == Kind::Random) return random_way();
    // Without a branch on the stamps, whose order is random (a mispredicted branch costs the
    // host more than the compares).
    const uint64_t* stamps = stamps_.data() + size_t(set) * ways_;
    uint32_t oldest = 0;
    uint64_t oldest_stamp = stamps[0];
    for (uint32_t w = 1; w < ways_; ++w) {
      bool older = stamps[w] < oldest_stamp;
      oldest = older ? w : oldest;
      oldest_stamp = older ? stamps[w] : oldest_stamp;
    }
    return oldest;
  }

 private:
  uint32_t random_way();
  Kind kind_ = Kind::Lru;
  uint32_t ways_ = 0;
  std::vector<uint64_t> stamps_;
  uint64_t clock_ = 0;
  uint64_t state_ = 1;  // random: the xorshift state
};

// "lru", "fifo" or "random" (seeded, deterministic); none for an unknown name.
std::optional<ReplacementPolicy> make_replacement_policy(const std::string& name, uint32_t sets,
                                                         uint32_t ways, uint64_t seed = 1);
std::vector<std::string> replacement_policy_names();

}  // namespace rtsim
