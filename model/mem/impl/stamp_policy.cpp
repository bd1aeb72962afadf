// LRU and FIFO: both evict the way with the oldest stamp; they differ in when a stamp is set
// (LRU on every touch, FIFO only on insert). Random: a seeded xorshift, so runs are repeatable.
#include <algorithm>

#include "model/mem/replacement.h"

namespace rtsim {
namespace {

class StampPolicy : public ReplacementPolicy {
 public:
  StampPolicy(uint32_t sets, uint32_t ways, bool stamp_on_touch)
      : ways_(ways), stamps_(size_t(sets) * ways, 0), stamp_on_touch_(stamp_on_touch) {}
  void touch(uint32_t set, uint32_t way) override {
    if (stamp_on_touch_) stamps_[size_t(set) * ways_ + way] = ++clock_;
  }
  void insert(uint32_t set, uint32_t way) override {
    stamps_[size_t(set) * ways_ + way] = ++clock_;
  }
  uint32_t victim(uint32_t set) override {
    auto first = stamps_.begin() + long(size_t(set) * ways_);
    return uint32_t(std::min_element(first, first + ways_) - first);
  }

 private:
  uint32_t ways_;
  std::vector<uint64_t> stamps_;
  uint64_t clock_ = 0;
  bool stamp_on_touch_;
};

class RandomPolicy : public ReplacementPolicy {
 public:
  RandomPolicy(uint32_t ways, uint64_t seed) : ways_(ways), state_(seed | 1) {}
  void touch(uint32_t, uint32_t) override {}
  void insert(uint32_t, uint32_t) override {}
  uint32_t victim(uint32_t) override {
    state_ ^= state_ << 13;
    state_ ^= state_ >> 7;
    state_ ^= state_ << 17;
    return uint32_t(state_ % ways_);
  }

 private:
  uint32_t ways_;
  uint64_t state_;
};

}  // namespace

std::unique_ptr<ReplacementPolicy> make_replacement_policy(const std::string& name, uint32_t sets,
                                                           uint32_t ways, uint64_t seed) {
  if (name == "lru") return std::make_unique<StampPolicy>(sets, ways, true);
  if (name == "fifo") return std::make_unique<StampPolicy>(sets, ways, false);
  if (name == "random") return std::make_unique<RandomPolicy>(ways, seed);
  return nullptr;
}

std::vector<std::string> replacement_policy_names() {
  return {"lru", "fifo", "random"};
}

}  // namespace rtsim
