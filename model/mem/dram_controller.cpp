#include "model/mem/dram_controller.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace rtsim {
namespace {

bool same_bank(const DramAddress& x, const DramAddress& y) {
  return x.rank == y.rank && x.group == y.group && x.bank == y.bank;
}

bool same_row(const DramAddress& x, const DramAddress& y) {
  return x.channel == y.channel && same_bank(x, y) && x.row == y.row;
}

const BankedDramConfig& checked(const BankedDramConfig& config) {
  std::string problem = banked_dram_config_problem(config);
  if (!problem.empty()) throw std::invalid_argument(problem);
  return config;
}

constexpr DramCommand column_command(bool write) {
  return write ? DramCommand::Wr : DramCommand::Rd;
}

// a * b / c rounded down or up, without overflow for clocks of any simulation. In 64 bits where
// the product fits (b and c are a reduced ratio: always, in practice), since a 128-bit division
// is a library call several times slower.
uint64_t mul_div(uint64_t a, uint64_t b, uint64_t c, bool up) {
  uint64_t product;
  if (!__builtin_mul_overflow(a, b, &product) && product <= ~uint64_t(0) - c)
    return (product + (up ? c - 1 : 0)) / c;
  return uint64_t(((unsigned __int128)a * b + (up ? c - 1 : 0)) / c);
}

}  // namespace

DramController::DramController(const BankedDramConfig& config, double core_ghz)
    : config_(config),
      map_(checked(config)),
      core_rate_(uint64_t(core_ghz * 1e6 + 0.5)),
      dram_rate_(uint64_t(config.clock_mhz * 1e3 + 0.5)) {
  uint64_t common = std::gcd(core_rate_, dram_rate_);  // the same conversions, in smaller numbers
  core_rate_ /= common;
  dram_rate_ /= common;
  for (uint32_t c = 0; c < config.channels; ++c) {
    channels_.emplace_back(config);
    for (uint32_t r = 0; r < config.ranks; ++r) {  // ranks refresh in turn, tREFI apart in all
      DramClock interval =
          config.refresh == DramRefresh::PerBank ? config.timing.tREFIpb : config.timing.tREFI;
      channels_.back().refresh.push_back({interval * (r + 1) / config.ranks, 0});
    }
    set_refresh_due(channels_.back());
  }
}

DramClock DramController::to_dram(Cycle core) const {
  return mul_div(core, dram_rate_, core_rate_, true);
}

Cycle DramController::to_core(DramClock clock) const {
  return mul_div(clock, core_rate_, dram_rate_, true);
}

size_t DramController::queued() const {
  size_t n = 0;
  for (const Channel& ch : channels_) n += ch.reads.size() + ch.writes.size() + ch.waiting.size();
  return n;
}

Cycle DramController::enqueue(uint64_t id, uint64_t addr, uint32_t bytes, bool write, Cycle at) {
  uint64_t burst = config_.burst_bytes();
  uint32_t shift = map_.burst_shift();
  uint64_t first = addr >> shift, last = (addr + std::max<uint32_t>(bytes, 1) - 1) >> shift;
  uint32_t request;
  if (free_requests_.empty()) {
    request = uint32_t(requests_.size());
    requests_.emplace_back();
  } else {
    request = free_requests_.back();
    free_requests_.pop_back();
  }
  requests_[request] = Request{id, at, uint32_t(last - first + 1), 0, write};
  (write ? stats_.writes : stats_.reads)++;
  (write ? stats_.write_bytes : stats_.read_bytes) += (last - first + 1) * burst;
  DramClock arrival = to_dram(at);
  Burst* last_entry = nullptr;
  DramClock next = kNever;
  for (uint64_t b = first; b <= last; ++b) {
    Burst entry{request, map_.decode_burst(b), arrival};
    if (last_entry && same_row(last_entry->a, entry.a) &&
        last_entry->a.column + last_entry->columns == entry.a.column) {
      last_entry->columns++;  // the next burst of the same row: one entry, one more RD
      continue;
    }
    Channel& ch = channels_[entry.a.channel];
    ch.waiting.push_back(entry);  // it joins its queue at its arrival (admit)
    last_entry = &ch.waiting.back();
    // Asleep, it wakes at a refresh it missed or at the arrival, whichever comes first.
    if (ch.next == kNever && config_.refresh != DramRefresh::None) ch.next = ch.refresh_due;
    ch.next = std::min(ch.next, arrival);
    next = std::min(next, ch.next);
  }
  return core_of(next);
}

Cycle DramController::next_event() const {
  DramClock next = kNever;
  for (const Channel& ch : channels_) next = std::min(next, ch.next);
  // A decision at clock d needs the requests up to the last core cycle before it.
  return next == kNever ? kPending : core_of(next);
}

Cycle DramController::core_of(DramClock clock) const {
  return mul_div(clock, core_rate_, dram_rate_, false);
}

void DramController::advance(Cycle until, std::vector<DramReadDone>& done) {
  DramClock last = mul_div(until + 1, dram_rate_, core_rate_, true) - 1;
  size_t first = done.size();
  for (Channel& ch : channels_)
    while (ch.next <= last) step(ch, ch.next, done);
  // In order of decision, a channel's in its order (a stable sort). A call completes a few
  // reads: sorted in place, as std::stable_sort would take a buffer from the heap each time.
  auto earlier = [](const DramReadDone& x, const DramReadDone& y) { return x.decided < y.decided; };
  constexpr size_t kInPlace = 32;
  if (done.size() - first > kInPlace) {
    std::stable_sort(done.begin() + long(first), done.end(), earlier);
    return;
  }
  for (size_t i = first + 1; i < done.size(); ++i) {
    DramReadDone read = done[i];
    size_t j = i;
    for (; j > first && earlier(read, done[j - 1]); --j) done[j] = done[j - 1];
    done[j] = read;
  }
}

void DramController::admit(Channel& ch, DramClock t) {
  while (!ch.waiting.empty() && ch.waiting.front().arrival <= t) {
    const Burst& b = ch.waiting.front();
    bool write = requests_[b.request].write;
    std::vector<Burst>& queue = write ? ch.writes : ch.reads;
    if (queue.size() >= (write ? config_.write_queue : config_.read_queue)) return;
    queue.push_back(b);
    ch.waiting.pop_front();
  }
}

void DramController::step(Channel& ch, DramClock t, std::vector<DramReadDone>& done) {
  admit(ch, t);
  DramClock wake = kNever;
  bool issued = decide(ch, t, wake, done, false);
  if (issued) wake = kNever;  // the dry decision below finds it
  if (!ch.waiting.empty()) {  // the next arrival, or room for one its full queue holds back
    DramClock arrival = ch.waiting.front().arrival;
    if (arrival > t || issued) wake = std::min(wake, std::max(arrival, t + 1));
  }
  if (issued) t++;  // the next decision is at t + 1 at the earliest
  bool idle = ch.reads.empty() && ch.writes.empty() && ch.waiting.empty();
  bool refresh_due = config_.refresh != DramRefresh::None && ch.refresh_due <= t;
  if (idle && !refresh_due) {
    ch.draining = false;  // as a decision finds with no write queued
    ch.next = kNever;     // asleep until a request arrives
    return;
  }
  // When the next command may issue, without a decision at each clock between.
  if (issued) decide(ch, t, wake, done, true);
  ch.next = std::max(wake, issued ? t : t + 1);
}

bool DramController::decide(Channel& ch, DramClock t, DramClock& wake,
                            std::vector<DramReadDone>& done, bool dry) {
  ch.rows_valid = false;
  if (config_.refresh != DramRefresh::None) {
    if (ch.refresh_due > t)  // the common case, without a call
      wake = std::min(wake, ch.refresh_due);
    else if (refresh(ch, t, wake, dry))
      return true;
  }
  if (ch.draining && ch.writes.size() <= config_.write_low) ch.draining = false;
  if (!ch.draining && ch.writes.size() >= config_.write_high) ch.draining = true;
  bool write = ch.draining || ch.reads.empty();
  std::vector<Burst>& first = write ? ch.writes : ch.reads;
  std::vector<Burst>& second = write ? ch.reads : ch.writes;
  return (!first.empty() && schedule(ch, first, write, t, wake, done, dry)) ||
         (!second.empty() && schedule(ch, second, !write, t, wake, done, dry));
}

bool DramController::blocked(const Channel& ch, const Burst& b, DramClock t) const {
  if (config_.refresh == DramRefresh::None) return false;
  if (ch.refresh_due > t) return false;
  const RankRefresh& r = ch.refresh[b.a.rank];
  if (r.due > t || activated_for(ch, b)) return false;
  return config_.refresh == DramRefresh::AllBank ||
         r.bank == b.a.group * config_.banks_per_group + b.a.bank;
}

bool DramController::activated_for(const Channel& ch, const Burst& b) const {
  return b.opened && ch.device.open_row(b.a) == b.a.row;
}

const std::vector<uint8_t>& DramController::rows(Channel& ch) const {
  if (ch.rows_valid) return ch.rows;
  ch.rows_valid = true;
  ch.rows.assign(size_t(config_.ranks) * config_.banks(), 0);
  for (const std::vector<Burst>* q : {&ch.reads, &ch.writes})
    for (const Burst& b : *q)
      if (ch.device.open_row(b.a) == b.a.row)
        ch.rows[bank_of(b.a)] |= b.opened ? kWanted | kHeld : kWanted;
  return ch.rows;
}

void DramController::set_refresh_due(Channel& ch) const {
  ch.refresh_due = kNever;
  for (const RankRefresh& r : ch.refresh) ch.refresh_due = std::min(ch.refresh_due, r.due);
}

void DramController::mark_opened(Channel& ch, const Burst& b) {
  auto mark = [&](Burst& o) {
    if (o.request == b.request && same_row(o.a, b.a)) o.opened = true;
  };
  for (Burst& o : ch.reads) mark(o);
  for (Burst& o : ch.writes) mark(o);
  for (Burst& o : ch.waiting) mark(o);
}

bool DramController::refresh(Channel& ch, DramClock t, DramClock& wake, bool dry) {
  bool per_bank = config_.refresh == DramRefresh::PerBank;
  for (uint32_t rank = 0; rank < config_.ranks; ++rank) {
    RankRefresh& r = ch.refresh[rank];
    if (r.due > t) {
      wake = std::min(wake, r.due);
      continue;
    }
    // Close what is open (the rank's banks, or the one bank), then refresh. A row opened for a
    // request that waits is closed after it (the refresh is postponed: JEDEC allows several).
    DramAddress pre{};
    DramClock pre_at = kNever;
    bool held = false;
    uint32_t first = per_bank ? r.bank : 0, count = per_bank ? 1 : config_.banks();
    const DramAddress first_bank{
        0, rank, first / config_.banks_per_group, first % config_.banks_per_group, 0, 0};
    DramAddress a = first_bank;
    for (uint32_t i = 0; i < count; ++i, next_bank(a)) {
      if (ch.device.open_row(a) == DramChannel::kClosed) continue;
      if (rows(ch)[bank_of(a)] & kHeld) {
        held = true;
        continue;
      }
      DramClock e = ch.device.earliest(DramCommand::Pre, a, t);
      if (e < pre_at) pre_at = e, pre = a;
    }
    if (pre_at != kNever) {
      if (pre_at > t || dry) {
        wake = std::min(wake, pre_at);
        continue;
      }
      ch.device.issue(DramCommand::Pre, pre, t);
      stats_.commands.pre++;
      return true;
    }
    if (held) continue;  // the request's column command lowers wake
    DramCommand command = per_bank ? DramCommand::RefPb : DramCommand::Ref;
    DramClock e = ch.device.earliest(command, first_bank, t);
    if (e > t || dry) {
      wake = std::min(wake, e);
      continue;
    }
    ch.device.issue(command, first_bank, t);
    (per_bank ? stats_.commands.ref_pb : stats_.commands.ref)++;
    bool waited = false;
    for (const std::vector<Burst>* q : {&ch.reads, &ch.writes})
      for (const Burst& b : *q) waited = waited || blocked(ch, b, t);
    if (waited)
      stats_.refresh_stall_clocks += per_bank ? config_.timing.tRFCpb : config_.timing.tRFC;
    r.due += per_bank ? config_.timing.tREFIpb : config_.timing.tREFI;
    if (per_bank) r.bank = (r.bank + 1) % config_.banks();
    set_refresh_due(ch);
    return true;
  }
  return false;
}

bool DramController::schedule(Channel& ch, std::vector<Burst>& queue, bool write, DramClock t,
                              DramClock& wake, std::vector<DramReadDone>& done, bool dry) {
  if (dry && wake <= t) return false;  // the next decision is at t: nothing can lower wake
  DramChannel& dev = ch.device;
  // Only a refresh that is due blocks requests.
  bool refreshing = config_.refresh != DramRefresh::None && ch.refresh_due <= t;
  Burst* const end = queue.data() + queue.size();
  Burst* oldest = queue.data();
  while (refreshing && oldest != end && blocked(ch, *oldest, t)) ++oldest;
  if (oldest == end) return false;
  // Past the cap, the oldest request's bank is kept for it: no younger request to that bank
  // issues, except one whose row was opened for it (so every ACT is used).
  bool capped = oldest->bypassed >= config_.starvation_cap;
  auto held_back = [&](const Burst* b) {
    return capped && b != oldest && same_bank(b->a, oldest->a) && !b->opened;
  };
  // FR-FCFS in one pass, oldest first: the first row hit whose column command can issue now;
  // failing that, the first other request whose next command (ACT, or PRE for another row) can.
  // A row stays open while a request it was opened for waits, and, unless this request is past
  // the cap, while any queued request hits it.
  Burst* first_come = nullptr;
  DramCommand first_command = DramCommand::Act;
  for (Burst* i = oldest; i != end; ++i) {
    Burst& b = *i;
    if ((refreshing && blocked(ch, b, t)) || held_back(i)) continue;
    uint32_t row = dev.open_row(b.a);
    DramCommand command = row == b.a.row                ? column_command(write)
                          : row == DramChannel::kClosed ? DramCommand::Act
                                                        : DramCommand::Pre;
    if (command == DramCommand::Pre &&
        (rows(ch)[bank_of(b.a)] & (capped && i == oldest ? kHeld : kWanted)))
      continue;
    bool hit = row == b.a.row;
    if (!hit && first_come) continue;  // only the first of them can issue
    DramClock e = dev.earliest(command, b.a, t);
    if (e > t || dry) {
      wake = std::min(wake, e);
      if (dry && wake <= t) return false;  // no later request can lower it
      continue;
    }
    if (!hit) {
      first_come = i;
      first_command = command;
      continue;
    }
    for (Burst* j = oldest; j != i; ++j)
      if (same_bank(j->a, b.a) && j->a.row != b.a.row) j->bypassed++;
    serve_column(ch, queue, size_t(i - queue.data()), write, t, done);
    return true;
  }
  if (!first_come) return false;
  Burst& b = *first_come;
  dev.issue(first_command, b.a, t);
  if (first_command == DramCommand::Act) {
    b.needed_act = true;
    mark_opened(ch, b);
    stats_.commands.act++;
  } else {
    b.needed_pre = true;
    stats_.commands.pre++;
  }
  return true;
}

void DramController::serve_column(Channel& ch, std::vector<Burst>& queue, size_t index, bool write,
                                  DramClock t, std::vector<DramReadDone>& done) {
  Burst b = queue[index];
  if (b.columns > 1) {  // its next burst stays queued, a row hit to come
    Burst& rest = queue[index];
    rest.columns--;
    rest.a.column++;
    rest.needed_act = rest.needed_pre = false;
  } else {
    queue.erase(queue.begin() + long(index));
  }
  bool close = false;
  if (config_.page_policy == DramPagePolicy::Closed) {
    // unless another request that has arrived wants the row
    auto wants = [&](const Burst& o) { return o.arrival <= t && same_row(o.a, b.a); };
    close = std::none_of(ch.reads.begin(), ch.reads.end(), wants) &&
            std::none_of(ch.writes.begin(), ch.writes.end(), wants) &&
            std::none_of(ch.waiting.begin(), ch.waiting.end(), wants);
  }
  DramClock data_end = ch.device.issue(column_command(write), b.a, t, close);
  (write ? stats_.commands.wr : stats_.commands.rd)++;
  if (close) stats_.commands.pre++;
  if (b.needed_pre)
    stats_.row_conflicts++;
  else if (b.needed_act)
    stats_.row_misses++;
  else
    stats_.row_hits++;
  if (ch.used && write != ch.last_write) stats_.turnarounds++;
  ch.used = true;
  ch.last_write = write;
  stats_.queued_burst_clocks += double(t - b.arrival);
  Request& r = requests_[b.request];
  r.data_end = std::max(r.data_end, data_end);
  if (--r.bursts > 0) return;
  free_requests_.push_back(b.request);
  if (r.write) return;
  Cycle ready = to_core(r.data_end) + config_.controller_latency;
  stats_.read_latency.add(ready - r.arrival);
  done.push_back({r.id, ready, core_of(t)});
}

}  // namespace rtsim
