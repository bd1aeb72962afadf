#include "model/mem/cache.h"

#include <algorithm>
#include <stdexcept>

#include "model/mem/way_search.h"

namespace rtsim {
namespace {

bool power_of_two(uint64_t x) {
  return x && !(x & (x - 1));
}

// Whether the first reference to a block is this cache's own fetch, for a given share: a
// splitmix64 hash of the block, as a fraction of 2^64, below the share.
bool fetched_here(uint64_t block, double share) {
  uint64_t z = block + 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  z ^= z >> 31;
  return double(z) < share * 18446744073709551616.0;
}

}  // namespace

CacheStats& CacheStats::operator+=(const CacheStats& o) {
  for (auto [mine, theirs] : {std::pair{&accesses, o.accesses},
                              {&hits, o.hits},
                              {&misses, o.misses},
                              {&cold_misses, o.cold_misses},
                              {&absent_fills, o.absent_fills},
                              {&mshr_merges, o.mshr_merges},
                              {&merge_limit_stalls, o.merge_limit_stalls},
                              {&mshr_stall_cycles, o.mshr_stall_cycles},
                              {&bank_conflicts, o.bank_conflicts},
                              {&bank_stall_cycles, o.bank_stall_cycles},
                              {&port_stall_cycles, o.port_stall_cycles},
                              {&evictions, o.evictions},
                              {&bytes_read, o.bytes_read},
                              {&bytes_below, o.bytes_below},
                              {&writes, o.writes},
                              {&write_misses, o.write_misses},
                              {&write_bytes, o.write_bytes},
                              {&writebacks, o.writebacks},
                              {&writeback_bytes, o.writeback_bytes},
                              {&local_reads, o.local_reads},
                              {&local_misses, o.local_misses},
                              {&prefetches, o.prefetches},
                              {&prefetch_redundant, o.prefetch_redundant},
                              {&prefetch_useful, o.prefetch_useful},
                              {&prefetch_late, o.prefetch_late},
                              {&prefetch_useless, o.prefetch_useless},
                              {&victims, o.victims},
                              {&victim_fills, o.victim_fills}})
    *mine += theirs;
  static_assert(sizeof(CacheStats) == 28 * sizeof(uint64_t), "a counter is missing above");
  return *this;
}

std::string cache_config_problem(const CacheConfig& c) {
  if (!power_of_two(c.line_bytes)) return "line_bytes must be a power of two";
  if (c.sector_bytes != 0 &&
      (!power_of_two(c.sector_bytes) || c.sector_bytes > c.line_bytes || c.sector_bytes < 4))
    return "sector_bytes must be 0 or a power of two from 4 to line_bytes";
  if (c.ways == 0) return "ways must be at least 1";
  if (c.size_bytes == 0 || c.size_bytes % (uint64_t(c.line_bytes) * c.ways) != 0)
    return "size_bytes must be a positive multiple of line_bytes * ways";
  if (c.mshrs == 0) return "mshrs must be at least 1";
  if (c.merge_limit > 65535) return "merge_limit must be at most 65535";
  if (!power_of_two(c.banks)) return "banks must be a power of two";
  if (!(c.bytes_per_cycle >= 0)) return "bytes_per_cycle must be 0 (no limit) or positive";
  if (!make_replacement_policy(c.replacement, 1, 1))
    return "replacement '" + c.replacement + "' is unknown (lru, fifo, random)";
  return {};
}

Cache::Cache(const CacheConfig& config, MemoryTarget* below, const CachePlace& place)
    : config_(config), below_(below), place_(place) {
  std::string problem = cache_config_problem(config);
  if (!problem.empty()) throw std::invalid_argument(problem);
  sets_ = uint32_t(config.size_bytes / (uint64_t(config.line_bytes) * config.ways));
  if (sets_ > 1 && power_of_two(sets_)) set_shift_ = uint32_t(__builtin_ctz(sets_));
  line_shift_ = uint32_t(__builtin_ctz(config.line_bytes));
  block_shift_ = uint32_t(__builtin_ctz(rtsim::block_bytes(config)));
  sector_shift_ = line_shift_ - block_shift_;
  sector_mask_ = (uint64_t(1) << sector_shift_) - 1;
  admits_ = config.bank_ports > 0 || config.bytes_per_cycle > 0;
  tags_.assign(size_t(sets_) * config.ways, kNoTag);
  filled_.assign(sets_, 0);
  blocks_.resize(tags_.size() << sector_shift_);
  banks_.resize(config.banks);
  policy_ = *make_replacement_policy(config.replacement, sets_, config.ways);
  for (uint32_t i = 0; i < config.mshrs; ++i) free_mshrs_.push(0);
}

uint64_t Cache::host_bytes(const CacheConfig& c) {
  uint64_t lines = c.size_bytes / c.line_bytes;
  uint64_t blocks_per_line = c.line_bytes / rtsim::block_bytes(c);
  return lines * (sizeof(uint64_t) + blocks_per_line * sizeof(Block)) +
         lines / c.ways * sizeof(uint32_t);
}

Cycle Cache::admit(uint64_t line, uint64_t bytes, Cycle at) {
  Cycle start = at;
  if (config_.bank_ports > 0) {
    Bank& bank = banks_[line & (config_.banks - 1)];
    if (bank.cycle < at) bank = {at, 0};
    if (bank.used == config_.bank_ports) bank = {bank.cycle + 1, 0};
    bank.used++;
    if (bank.cycle > at) {
      stats_.bank_conflicts++;
      stats_.bank_stall_cycles += bank.cycle - at;
    }
    start = bank.cycle;
  }
  if (config_.bytes_per_cycle > 0) {
    double begin = std::max(double(start), port_free_);
    port_free_ = begin + double(bytes) / config_.bytes_per_cycle;
    auto cycle = Cycle(begin);  // it starts within that cycle
    stats_.port_stall_cycles += cycle - start;
    start = cycle;
  }
  return start;
}

Cycle Cache::read(uint64_t addr, uint32_t bytes, Cycle at, ReadClient* client, uint64_t token,
                  ReadCharge& charge) {
  uint64_t first = addr >> block_shift_;
  uint64_t last = (addr + std::max<uint32_t>(bytes, 1) - 1) >> block_shift_;
  stats_.bytes_read += bytes;
  if (addr >= kLocalMemoryBase) stats_.local_reads++;
  Caller caller{client, token, last > first, kNone};
  if (!caller.several_blocks) {
    Place p = look_up(first >> sector_shift_);
    return read_block(first, p, admits_ ? admit(first >> sector_shift_, bytes, at) : at, caller,
                      charge);
  }
  // Block by block, the hot path (a node's several lines), looking each line up once, at the
  // read's first block in it; a line takes its bank and port for the part of the read inside it.
  Cycle ready = at, start = at;
  Place p{0, kNone};
  for (uint64_t block = first; block <= last; ++block) {
    if ((block & sector_mask_) == 0 || block == first) {  // the read's first block in this line
      uint64_t line = block >> sector_shift_;
      if (admits_) {
        uint64_t begin = std::max(addr, line << line_shift_);
        start = admit(line, std::min(addr + bytes, (line + 1) << line_shift_) - begin, at);
      }
      p = look_up(line);
    }
    Cycle r = read_block(block, p, start, caller, charge);
    if (r != kPending) ready = std::max(ready, r);
  }
  if (caller.request == kNone) return ready;
  Request& q = requests_[caller.request];  // its blocks complete later, never during this call
  q.ready = std::max(q.ready, ready);
  return kPending;
}

void Cache::prime(uint64_t addr) const {
  uint64_t block = addr >> block_shift_;
  uint32_t set = set_of(block >> sector_shift_);
  prefetch_span(&tags_[size_t(set) * config_.ways], config_.ways * sizeof(uint64_t), 64);
  // The block of addr in each way: the ways' blocks of one sector lie a line's blocks apart.
  size_t way_bytes = sizeof(Block) << sector_shift_;
  prefetch_span(&blocks_[block_index(set, 0, block)], config_.ways * way_bytes,
                std::max<size_t>(way_bytes, 64));
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
  // Line by line: each takes its bank and port, and goes below on its own (the level below may
  // place lines apart: the slices of the L2).
  for_each_line(addr, bytes, [&](uint64_t line, uint64_t begin, uint64_t stop) {
    Cycle start = admits_ ? admit(line, stop - begin, at) : at;
    for (uint64_t block = begin >> block_shift_; block <= (stop - 1) >> block_shift_; ++block)
      write_block(block, start);
    if (!config_.write_back)
      below_->write(begin, uint32_t(stop - begin), start + config_.hit_latency);
  });
}

void Cache::prefetch(uint64_t addr, uint32_t bytes, Cycle at) {
  for_each_line(addr, bytes, [&](uint64_t line, uint64_t begin, uint64_t stop) {
    Cycle start = admits_ ? admit(line, stop - begin, at) : at;  // its bank and data port
    uint32_t set = set_of(line);
    uint32_t way = find(set, tag_of(line));
    for (uint64_t block = begin >> block_shift_; block <= (stop - 1) >> block_shift_; ++block) {
      if (way != kNone && block_at(set, way, block).valid) {
        stats_.prefetch_redundant++;
        continue;
      }
      if (way == kNone) way = allocate(set, tag_of(line), start);
      if (track_cold_) first_reference(block);
      stats_.prefetches++;
      Caller nobody{nullptr, 0, false, kNone};
      ReadCharge charge;  // charged to no ray
      miss(block, set, way, start, nobody, charge);
      block_at(set, way, block).prefetched = true;
    }
  });
}

void Cache::fill(uint64_t addr, uint32_t bytes, Cycle at) {
  for_each_line(addr, bytes, [&](uint64_t line, uint64_t begin, uint64_t stop) {
    Cycle start = admits_ ? admit(line, stop - begin, at) : at;
    Place p = place(line, start);
    for (uint64_t block = begin >> block_shift_; block <= (stop - 1) >> block_shift_; ++block) {
      Block& b = block_at(p.set, p.way, block);
      if (b.valid) continue;
      b = Block{start, kNone, 0, true, false, false};
      stats_.victim_fills++;
      if (track_cold_) first_reference(block);
    }
  });
}

uint32_t Cache::warm(uint64_t addr, uint32_t bytes, Cycle at, bool write) {
  uint32_t fetched = 0;
  for_each_line(addr, bytes, [&](uint64_t line, uint64_t begin, uint64_t stop) {
    Place p = place(line, at);
    bool dirty = write && config_.write_back;
    for (uint64_t block = begin >> block_shift_; block <= (stop - 1) >> block_shift_; ++block) {
      Block& b = block_at(p.set, p.way, block);
      b.dirty = b.dirty || dirty;
      if (b.valid) continue;
      b = Block{0, kNone, 0, true, dirty, false};
      if (track_cold_) first_reference(block);
      fetched += !write && (block << block_shift_) < kLocalMemoryBase;
    }
  });
  return fetched;
}

bool Cache::contains(uint64_t addr) const {
  uint64_t block = addr >> block_shift_;
  uint64_t line = block >> sector_shift_;
  uint32_t set = set_of(line);
  uint32_t way = find(set, tag_of(line));
  return way != kNone && blocks_[block_index(set, way, block)].valid;
}

uint32_t Cache::find(uint32_t set, uint64_t tag) const {
  return find_way_(&tags_[size_t(set) * config_.ways], config_.ways, tag);
}

void Cache::track_cold_misses(uint64_t dense_begin, uint64_t dense_end) {
  track_cold_ = true;
  if (dense_end <= dense_begin) return;
  dense_first_ = dense_begin >> block_shift_;
  dense_blocks_ = ((dense_end - 1) >> block_shift_) - dense_first_ + 1;
  dense_held_.assign((dense_blocks_ + 63) / 64, 0);
}

uint32_t Cache::merge(Block& b) {
  stats_.mshr_merges++;
  if (config_.merge_limit > 0 && b.merges >= config_.merge_limit) {
    stats_.merge_limit_stalls++;
    return config_.hit_latency;
  }
  b.merges++;
  return 0;
}

Cache::Place Cache::place(uint64_t line, Cycle at) {
  Place p{set_of(line), find(set_of(line), tag_of(line))};
  if (p.way == kNone)
    p.way = allocate(p.set, tag_of(line), at);
  else
    policy_.touch(p.set, p.way);
  return p;
}

inline Cache::Place Cache::look_up(uint64_t line) {
  Place p{set_of(line), kNone};
  p.way = find(p.set, tag_of(line));
  if (p.way != kNone) policy_.touch(p.set, p.way);
  return p;
}

inline Cycle Cache::read_block(uint64_t block, Place& p, Cycle at, Caller& caller,
                               ReadCharge& charge) {
  stats_.accesses++;
  charge.add(place_.level, 1, 0);
  Cycle hit_ready = at + config_.hit_latency;

  if (p.way != kNone) {
    Block& b = block_at(p.set, p.way, block);
    if (b.prefetched) used_prefetch(b, at);
    if (b.valid && (b.ready == kPending || b.ready > at)) {
      uint32_t replay = merge(b);
      if (b.ready != kPending) return std::max(b.ready + replay, hit_ready);
      wait_for(b.miss, caller, hit_ready, replay);
      return kPending;
    }
    if (b.valid) {
      stats_.hits++;
      charge.hits[place_.level]++;
      return hit_ready;
    }
  }
  Absent a = read_absent(block, p.set, p.way, at, caller, charge);
  p.way = a.way;
  return a.ready;
}

Cache::Absent Cache::read_absent(uint64_t block, uint32_t set, uint32_t way, Cycle at,
                                 Caller& caller, ReadCharge& charge) {
  bool first = track_cold_ && first_reference(block);
  if (!place_.fill_on_miss) {
    if (first) stats_.cold_misses++;
    stats_.misses++;
    return {read_through(block, at, caller, charge), way};
  }
  if (way == kNone) way = allocate(set, tag_of(block >> sector_shift_), at);
  Cycle hit_ready = at + config_.hit_latency;
  if (first && own_share_ < 1.0 && !fetched_here(block, own_share_)) {
    stats_.hits++;
    stats_.absent_fills++;
    charge.hits[place_.level]++;
    // The absent client's fetch is in flight for a fetch's mean latency: reads until then merge.
    Cycle fetched = at + mean_fetch_cycles();
    block_at(set, way, block) = Block{std::max(hit_ready, fetched), kNone, 0, true, false, false};
    return {hit_ready, way};
  }
  if (first) stats_.cold_misses++;
  if ((block << block_shift_) >= kLocalMemoryBase) stats_.local_misses++;
  stats_.misses++;
  return {miss(block, set, way, at, caller, charge), way};
}

Cycle Cache::read_through(uint64_t block, Cycle at, Caller& caller, ReadCharge& charge) {
  if (caller.several_blocks || !caller.client)
    throw std::logic_error("a victim level reads a block at a time for the level above");
  stats_.bytes_below += block_bytes();
  if (place_.above_dram) charge.dram_bytes += block_bytes();
  return below_->read(block << block_shift_, block_bytes(), at + config_.hit_latency, caller.client,
                      caller.token, charge);
}

void Cache::write_block(uint64_t block, Cycle at) {
  stats_.writes++;
  uint64_t line = block >> sector_shift_;
  uint32_t set = set_of(line);
  uint32_t way = find(set, tag_of(line));
  if (way == kNone) way = allocate(set, tag_of(line), at);
  policy_.touch(set, way);
  Block& b = block_at(set, way, block);
  if (!b.valid) {
    stats_.write_misses++;
    // A read from `at` on finds it, after its tag check.
    b = Block{at, kNone, 0, true, false, false};
    if (track_cold_) first_reference(block);
  }
  b.dirty = config_.write_back;
}

void Cache::used_prefetch(Block& b, Cycle at) {
  b.prefetched = false;
  stats_.prefetch_useful++;
  if (b.ready == kPending || b.ready > at) stats_.prefetch_late++;
}

void Cache::wait_for(uint32_t miss, Caller& caller, Cycle earliest, uint32_t replay) {
  if (!caller.client) return;  // a prefetch
  if (!caller.several_blocks) {
    add_waiter(miss, {caller.client, caller.token, earliest, replay, kNone});
    return;
  }
  if (caller.request == kNone) {
    caller.request = take_slot(requests_, free_requests_);
    requests_[caller.request] = Request{caller.client, caller.token, 0, 0, {}};
  }
  requests_[caller.request].blocks++;
  add_waiter(miss, {&join_, caller.request, earliest, replay, kNone});
}

void Cache::add_waiter(uint32_t miss, const Waiter& waiter) {
  Miss& m = misses_[miss];
  if (!m.first.client) {
    m.first = waiter;
    return;
  }
  uint32_t id = take_slot(waiters_, free_waiters_);
  waiters_[id] = waiter;
  (m.last == kNone ? m.first.next : waiters_[m.last].next) = id;
  m.last = id;
}

void Cache::add_waiting(uint32_t miss) {
  misses_[miss].next_waiting = kNone;
  (waiting_last_ == kNone ? waiting_first_ : misses_[waiting_last_].next_waiting) = miss;
  waiting_last_ = miss;
}

uint32_t Cache::take_waiting() {
  uint32_t miss = waiting_first_;
  waiting_first_ = misses_[miss].next_waiting;
  if (waiting_first_ == kNone) waiting_last_ = kNone;
  return miss;
}

inline Cycle Cache::miss(uint64_t block, uint32_t set, uint32_t way, Cycle at, Caller& caller,
                         ReadCharge& charge) {
  stats_.bytes_below += block_bytes();
  if (place_.above_dram) charge.dram_bytes += block_bytes();
  Cycle send = at + config_.hit_latency;
  uint32_t id = take_slot(misses_, free_misses_);
  Block& b = block_at(set, way, block);
  b = Block{kPending, id, 0, true, false, false};
  Miss& m = misses_[id];
  m.block = block;
  m.way = way;
  m.send = send;
  m.prefetch = !caller.client;
  m.first.client = nullptr;
  m.first.next = m.last = kNone;
  // The MSHR free first; with none whose end is known, wait until one's end is reported.
  if (free_mshrs_.empty()) {
    wait_for(id, caller, 0, 0);
    add_waiting(id);
    return kPending;
  }
  Cycle start = std::max(send, free_mshrs_.top());
  free_mshrs_.pop();
  ReadCharge below;
  Cycle ready = issue(id, start, below);
  if (ready == kPending) {
    wait_for(id, caller, 0, 0);
    return kPending;
  }
  // Answered at once: the block is in flight until `ready`, and so is its MSHR.
  note_fetch(misses_[id], ready);
  charge += below;
  Block& filled = block_at(set, way, block);
  filled.ready = ready;
  filled.miss = kNone;
  free_mshrs_.push(ready);
  free_misses_.push_back(id);
  return ready;
}

Cycle Cache::issue(uint32_t miss, Cycle at, ReadCharge& below) {
  const Miss& m = misses_[miss];
  stats_.mshr_stall_cycles += at - m.send;
  Cycle ready = below_->read(m.block << block_shift_, block_bytes(), at, this, miss, below);
  Miss& sent = misses_[miss];
  sent.charged = ready == kPending && !below.empty();
  if (sent.charged) {
    if (charges_.size() < misses_.size()) charges_.resize(misses_.size());
    charges_[miss] = below;
  }
  return ready;
}

void Cache::read_done(uint64_t token, Cycle ready, const ReadCharge& charge) {
  auto id = uint32_t(token);
  Miss& m = misses_[id];
  note_fetch(m, ready);
  Block& b = block_at(set_of(m.block >> sector_shift_), m.way, m.block);
  if (b.valid && b.ready == kPending && b.miss == id) {
    b.ready = ready;
    b.miss = kNone;
  }
  ReadCharge first;  // what the miss cost below, for its first waiter (a prefetch's: nobody's)
  if (!m.prefetch) {
    if (m.charged) first = charges_[id];
    first += charge;
  }
  // Completing a waiter only notifies its client; nothing here adds a waiter or a miss.
  if (m.first.client) {
    Waiter head = m.first;
    uint32_t w = head.next;
    head.client->read_done(head.token, std::max(ready + head.replay, head.earliest), first);
    while (w != kNone) {
      Waiter waiter = waiters_[w];
      free_waiters_.push_back(w);
      waiter.client->read_done(waiter.token, std::max(ready + waiter.replay, waiter.earliest),
                               ReadCharge{});
      w = waiter.next;
    }
  }
  free_misses_.push_back(id);
  // Its MSHR is free from `ready`: for the first miss waiting for one, or for later misses.
  if (waiting_first_ == kNone) {
    free_mshrs_.push(ready);
    return;
  }
  uint32_t next = take_waiting();
  ReadCharge below;
  Cycle next_ready = issue(next, std::max(ready, misses_[next].send), below);
  if (next_ready != kPending) read_done(next, next_ready, below);
}

std::vector<Cache::WaitingRead> Cache::waiting() const {
  std::vector<bool> free(misses_.size(), false), for_mshr(misses_.size(), false);
  for (uint32_t id : free_misses_) free[id] = true;
  for (uint32_t id = waiting_first_; id != kNone; id = misses_[id].next_waiting)
    for_mshr[id] = true;
  std::vector<WaitingRead> reads;
  for (uint32_t id = 0; id < misses_.size(); ++id) {
    if (free[id]) continue;
    const Miss& m = misses_[id];
    WaitingRead read{{}, m.block << block_shift_, for_mshr[id], m.send};
    if (!m.first.client) {
      reads.push_back(read);
      continue;
    }
    for (const Waiter* w = &m.first;; w = &waiters_[w->next]) {
      read.origin = w->client->origin(w->token);
      reads.push_back(read);
      if (w->next == kNone) break;
    }
  }
  return reads;
}

ReadOrigin Cache::origin(uint64_t miss) const {
  const Waiter& w = misses_[miss].first;
  return w.client ? w.client->origin(w.token) : ReadOrigin{};
}

void Cache::complete_part(uint32_t request, Cycle ready, const ReadCharge& charge) {
  Request& q = requests_[request];
  q.ready = std::max(q.ready, ready);
  q.charge += charge;
  if (--q.blocks > 0) return;
  free_requests_.push_back(request);
  q.client->read_done(q.token, q.ready, q.charge);
}

uint32_t Cache::allocate(uint32_t set, uint64_t tag, Cycle at) {
  uint64_t* ways = &tags_[size_t(set) * config_.ways];
  // Lines are never invalidated, so a set's ways fill in order: the first free one is next.
  uint32_t victim = filled_[set] < config_.ways ? filled_[set]++ : config_.ways;
  if (victim == config_.ways) {
    victim = policy_.victim(set);
    stats_.evictions++;
    uint64_t old_line = ways[victim] * sets_ + set;
    Block* blocks = &blocks_[(size_t(set) * config_.ways + victim) << sector_shift_];
    for (uint64_t s = 0; s <= sector_mask_; ++s) {
      if (blocks[s].prefetched) stats_.prefetch_useless++;
      uint64_t old_addr = ((old_line << sector_shift_) + s) << block_shift_;
      if (blocks[s].valid && blocks[s].dirty) {
        stats_.writebacks++;
        stats_.writeback_bytes += block_bytes();
        below_->write(old_addr, block_bytes(), at + config_.hit_latency);
      } else if (place_.victims_below && blocks[s].valid && blocks[s].ready != kPending) {
        stats_.victims++;
        below_->fill(old_addr, block_bytes(), at + config_.hit_latency);
      }
      blocks[s] = Block{};
    }
  }
  ways[victim] = tag;
  policy_.insert(set, victim);
  return victim;
}

}  // namespace rtsim
