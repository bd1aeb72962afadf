#include "model/mem/cache.h"

#include <algorithm>
#include <stdexcept>

namespace rtsim {
namespace {

bool power_of_two(uint64_t x) {
  return x && !(x & (x - 1));
}

// Whether the first reference to a line is this cache's own fetch, for a given share: a
// splitmix64 hash of the line, as a fraction of 2^64, below the share.
bool fetched_here(uint64_t line, double share) {
  uint64_t z = line + 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  z ^= z >> 31;
  return double(z) < share * 18446744073709551616.0;
}

}  // namespace

std::string cache_config_problem(const CacheConfig& c) {
  if (!power_of_two(c.line_bytes)) return "line_bytes must be a power of two";
  if (c.ways == 0) return "ways must be at least 1";
  if (c.size_bytes == 0 || c.size_bytes % (uint64_t(c.line_bytes) * c.ways) != 0)
    return "size_bytes must be a positive multiple of line_bytes * ways";
  if (c.mshrs == 0) return "mshrs must be at least 1";
  if (!make_replacement_policy(c.replacement, 1, 1))
    return "replacement '" + c.replacement + "' is unknown (lru, fifo, random)";
  return {};
}

Cache::Cache(const CacheConfig& config, MemoryLevel* below) : config_(config), below_(below) {
  std::string problem = cache_config_problem(config);
  if (!problem.empty()) throw std::invalid_argument(problem);
  sets_ = uint32_t(config.size_bytes / (uint64_t(config.line_bytes) * config.ways));
  lines_.resize(size_t(sets_) * config.ways);
  policy_ = make_replacement_policy(config.replacement, sets_, config.ways);
}

Cycle Cache::read(uint64_t addr, uint32_t bytes, Cycle now) {
  uint64_t first = addr / config_.line_bytes;
  uint64_t last = (addr + std::max<uint32_t>(bytes, 1) - 1) / config_.line_bytes;
  Cycle ready = now;
  for (uint64_t line = first; line <= last; ++line) ready = std::max(ready, access_line(line, now));
  return ready;
}

bool Cache::contains(uint64_t addr) const {
  uint64_t line = addr / config_.line_bytes;
  const Line* set = &lines_[size_t(line % sets_) * config_.ways];
  return std::any_of(set, set + config_.ways,
                     [&](const Line& l) { return l.valid && l.tag == line / sets_; });
}

Cycle Cache::access_line(uint64_t line, Cycle now) {
  stats_.accesses++;
  auto set = uint32_t(line % sets_);
  uint64_t tag = line / sets_;
  Line* ways = &lines_[size_t(set) * config_.ways];
  Cycle hit_ready = now + config_.hit_latency;

  for (uint32_t w = 0; w < config_.ways; ++w) {
    if (!ways[w].valid || ways[w].tag != tag) continue;
    policy_->touch(set, w);
    if (ways[w].ready > now) {
      stats_.mshr_merges++;
      return std::max(ways[w].ready, hit_ready);
    }
    stats_.hits++;
    return hit_ready;
  }

  bool first = track_cold_ && held_lines_.insert(line).second;
  if (first && own_share_ < 1.0 && !fetched_here(line, own_share_)) {
    stats_.hits++;
    stats_.absent_fills++;
    install(set, ways, Line{tag, hit_ready, true});
    return hit_ready;
  }
  stats_.misses++;
  if (first) stats_.cold_misses++;
  Cycle issue = reserve_mshr(now) + config_.hit_latency;
  stats_.bytes_below += config_.line_bytes;
  Cycle ready = below_->read(line * config_.line_bytes, config_.line_bytes, issue);
  in_flight_.push(ready);
  install(set, ways, Line{tag, ready, true});
  return ready;
}

void Cache::install(uint32_t set, Line* ways, const Line& line) {
  uint32_t victim = config_.ways;
  for (uint32_t w = 0; w < config_.ways && victim == config_.ways; ++w)
    if (!ways[w].valid) victim = w;
  if (victim == config_.ways) {
    victim = policy_->victim(set);
    stats_.evictions++;
  }
  ways[victim] = line;
  policy_->insert(set, victim);
}

// The cycle a new miss can start: now, or when the earliest in-flight miss frees its MSHR.
Cycle Cache::reserve_mshr(Cycle now) {
  while (!in_flight_.empty() && in_flight_.top() <= now) in_flight_.pop();
  if (in_flight_.size() < config_.mshrs) return now;
  Cycle start = in_flight_.top();
  in_flight_.pop();
  stats_.mshr_stall_cycles += start - now;
  return start;
}

}  // namespace rtsim
