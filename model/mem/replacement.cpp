#include "model/mem/replacement.h"

namespace rtsim {

ReplacementPolicy::ReplacementPolicy(Kind kind, uint32_t sets, uint32_t ways, uint64_t seed)
    : kind_(kind), ways_(ways), state_(seed | 1) {
  if (kind != Kind::Random) stamps_.assign(size_t(sets) * ways, 0);
}

uint32_t ReplacementPolicy::random_way() {
  state_ ^= state_ << 13;
  state_ ^= state_ >> 7;
  state_ ^= state_ << 17;
  return uint32_t(state_ % ways_);
}

std::optional<ReplacementPolicy> make_replacement_policy(const std::string& name, uint32_t sets,
                                                         uint32_t ways, uint64_t seed) {
  using Kind = ReplacementPolicy::Kind;
  if (name == "lru") return ReplacementPolicy(Kind::Lru, sets, ways, seed);
  if (name == "fifo") return ReplacementPolicy(Kind::Fifo, sets, ways, seed);
  if (name == "random") return ReplacementPolicy(Kind::Random, sets, ways, seed);
  return std::nullopt;
}

std::vector<std::string> replacement_policy_names() {
  return {"lru", "fifo", "random"};
}

}  // namespace rtsim
