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

Cache::Cache(const CacheConfig& config, MemoryTarget* below, CacheRole role)
    : config_(config), below_(below), role_(role) {
  std::string problem = cache_config_problem(config);
  if (!problem.empty()) throw std::invalid_argument(problem);
  sets_ = uint32_t(config.size_bytes / (uint64_t(config.line_bytes) * config.ways));
  if (sets_ > 1 && power_of_two(sets_)) set_shift_ = uint32_t(__builtin_ctz(sets_));
  line_shift_ = uint32_t(__builtin_ctz(config.line_bytes));
  lines_.resize(size_t(sets_) * config.ways);
  policy_ = make_replacement_policy(config.replacement, sets_, config.ways);
  for (uint32_t i = 0; i < config.mshrs; ++i) free_mshrs_.push(0);
}

template <class T>
uint32_t Cache::take(std::vector<T>& pool, std::vector<uint32_t>& free) {
  if (free.empty()) {
    pool.emplace_back();
    return uint32_t(pool.size() - 1);
  }
  uint32_t id = free.back();
  free.pop_back();
  return id;
}

Cycle Cache::read(uint64_t addr, uint32_t bytes, Cycle at, ReadClient* client, uint64_t token,
                  ReadCharge& charge) {
  uint64_t first = addr >> line_shift_;
  uint64_t last = (addr + std::max<uint32_t>(bytes, 1) - 1) >> line_shift_;
  Caller caller{client, token, last > first, kNone};
  if (!caller.several_lines) return access_line(first, at, caller, charge);
  Cycle ready = at;
  for (uint64_t line = first; line <= last; ++line) {
    Cycle r = access_line(line, at, caller, charge);
    if (r != kPending) ready = std::max(ready, r);
  }
  if (caller.request == kNone) return ready;
  Request& q = requests_[caller.request];  // its lines complete later, never during this call
  q.ready = std::max(q.ready, ready);
  return kPending;
}

Cycle Cache::read(uint64_t addr, uint32_t bytes, Cycle at) {
  ReadCharge charge;
  Cycle ready = read(addr, bytes, at, nullptr, 0, charge);
  if (ready == kPending)
    throw std::logic_error("Cache::read: a level below did not answer at once");
  return ready;
}

void Cache::write(uint64_t addr, uint32_t bytes, Cycle at) {
  stats_.write_bytes += bytes;
  below_->write(addr, bytes, at + config_.hit_latency);  // through the level's pipeline
}

bool Cache::contains(uint64_t addr) const {
  uint64_t line = addr >> line_shift_;
  const Line* set = &lines_[size_t(set_of(line)) * config_.ways];
  return std::any_of(set, set + config_.ways,
                     [&](const Line& l) { return l.valid && l.tag == tag_of(line); });
}

Cycle Cache::access_line(uint64_t line, Cycle at, Caller& caller, ReadCharge& charge) {
  stats_.accesses++;
  bool l1 = role_ == CacheRole::L1;
  (l1 ? charge.l1_accesses : charge.l2_accesses)++;
  uint32_t set = set_of(line);
  uint64_t tag = tag_of(line);
  Line* ways = &lines_[size_t(set) * config_.ways];
  Cycle hit_ready = at + config_.hit_latency;

  for (uint32_t w = 0; w < config_.ways; ++w) {
    Line& l = ways[w];
    if (!l.valid || l.tag != tag) continue;
    policy_->touch(set, w);
    if (l.ready == kPending) {
      stats_.mshr_merges++;
      wait_for(l.miss, caller, hit_ready);
      return kPending;
    }
    if (l.ready > at) {
      stats_.mshr_merges++;
      return std::max(l.ready, hit_ready);
    }
    stats_.hits++;
    (l1 ? charge.l1_hits : charge.l2_hits)++;
    return hit_ready;
  }

  bool first = track_cold_ && held_lines_.insert(line).second;
  if (first && own_share_ < 1.0 && !fetched_here(line, own_share_)) {
    stats_.hits++;
    stats_.absent_fills++;
    (l1 ? charge.l1_hits : charge.l2_hits)++;
    install(set, ways, Line{tag, hit_ready, kNone, true});
    return hit_ready;
  }
  if (first) stats_.cold_misses++;
  return miss(line, set, ways, at, caller, charge);
}

void Cache::wait_for(uint32_t miss, Caller& caller, Cycle earliest) {
  if (!caller.several_lines) {
    add_waiter(miss, {caller.client, caller.token, earliest, kNone});
    return;
  }
  if (caller.request == kNone) {
    caller.request = take(requests_, free_requests_);
    requests_[caller.request] = Request{caller.client, caller.token, 0, 0, {}};
  }
  requests_[caller.request].lines++;
  add_waiter(miss, {&join_, caller.request, earliest, kNone});
}

void Cache::add_waiter(uint32_t miss, const Waiter& waiter) {
  uint32_t id = take(waiters_, free_waiters_);
  waiters_[id] = waiter;
  Miss& m = misses_[miss];
  (m.first == kNone ? m.first : waiters_[m.last].next) = id;
  m.last = id;
}

Cycle Cache::miss(uint64_t line, uint32_t set, Line* ways, Cycle at, Caller& caller,
                  ReadCharge& charge) {
  stats_.misses++;
  stats_.bytes_below += config_.line_bytes;
  if (role_ == CacheRole::L2) charge.dram_bytes += config_.line_bytes;
  Cycle send = at + config_.hit_latency;
  uint32_t id = take(misses_, free_misses_);
  uint32_t way = install(set, ways, Line{tag_of(line), kPending, id, true});
  Miss& m = misses_[id];
  m.line = line;
  m.set = set;
  m.way = way;
  m.send = send;
  m.charge = {};
  m.first = m.last = kNone;
  // The MSHR free first; with none whose end is known, wait until one's end is reported.
  if (free_mshrs_.empty()) {
    wait_for(id, caller, 0);
    waiting_.push_back(id);
    return kPending;
  }
  Cycle start = std::max(send, free_mshrs_.top());
  free_mshrs_.pop();
  Cycle ready = issue(id, start);
  if (ready == kPending) {
    wait_for(id, caller, 0);
    return kPending;
  }
  // Answered at once: the line is in flight until `ready`, and so is its MSHR.
  charge += misses_[id].charge;
  ways[way].ready = ready;
  ways[way].miss = kNone;
  free_mshrs_.push(ready);
  free_misses_.push_back(id);
  return ready;
}

Cycle Cache::issue(uint32_t miss, Cycle at) {
  Miss& m = misses_[miss];
  stats_.mshr_stall_cycles += at - m.send;
  ReadCharge below;
  Cycle ready = below_->read(m.line << line_shift_, config_.line_bytes, at, this, miss, below);
  misses_[miss].charge += below;
  return ready;
}

void Cache::read_done(uint64_t token, Cycle ready, const ReadCharge& charge) {
  auto id = uint32_t(token);
  Miss& m = misses_[id];
  Line& line = lines_[size_t(m.set) * config_.ways + m.way];
  if (line.valid && line.ready == kPending && line.miss == id) line.ready = ready;
  ReadCharge first = m.charge;
  first += charge;
  // Completing a waiter only notifies its client; nothing here adds a waiter or a miss.
  uint32_t head = m.first;
  for (uint32_t w = head; w != kNone;) {
    Waiter waiter = waiters_[w];
    free_waiters_.push_back(w);
    waiter.client->read_done(waiter.token, std::max(ready, waiter.earliest),
                             w == head ? first : ReadCharge{});
    w = waiter.next;
  }
  free_misses_.push_back(id);
  // Its MSHR is free from `ready`: for the first miss waiting for one, or for later misses.
  if (waiting_.empty()) {
    free_mshrs_.push(ready);
    return;
  }
  uint32_t next = waiting_.front();
  waiting_.pop_front();
  Cycle next_ready = issue(next, std::max(ready, misses_[next].send));
  if (next_ready != kPending) read_done(next, next_ready, {});
}

void Cache::complete_part(uint32_t request, Cycle ready, const ReadCharge& charge) {
  Request& q = requests_[request];
  q.ready = std::max(q.ready, ready);
  q.charge += charge;
  if (--q.lines > 0) return;
  free_requests_.push_back(request);
  q.client->read_done(q.token, q.ready, q.charge);
}

uint32_t Cache::install(uint32_t set, Line* ways, const Line& line) {
  uint32_t victim = config_.ways;
  for (uint32_t w = 0; w < config_.ways && victim == config_.ways; ++w)
    if (!ways[w].valid) victim = w;
  if (victim == config_.ways) {
    victim = policy_->victim(set);
    stats_.evictions++;
  }
  ways[victim] = line;
  policy_->insert(set, victim);
  return victim;
}

}  // namespace rtsim
