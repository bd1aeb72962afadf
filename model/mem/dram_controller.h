// The memory controller of the banked DRAM: per channel a read queue and a write queue of
// bursts, scheduled FR-FCFS (the oldest row hit that can issue first, else the oldest request's
// next command) with a starvation cap, open- or closed-page, writes drained between a high and
// a low watermark, and refresh (all-bank or per-bank) that blocks its rank or bank. Commands go
// to the channel's DramChannel (dram_device.h), one per clock.
// Requests arrive in core cycles, in non-decreasing order; a request is split into bursts (a
// 64-byte line is two GDDR6 bursts), each mapped on its own (dram_address.h), and joins its
// channel's queue at its arrival clock: a request enqueued ahead of its cycle changes no decision
// taken before it, so the controller may be advanced late. A read completes
// when its last burst's data has crossed the bus, plus controller_latency. The controller works
// only at clocks where a command may issue: advance() jumps from one to the next, and a channel
// with empty queues sleeps; the refreshes it missed while asleep are issued at their own clocks
// when it wakes.
#pragma once

#include <cstdint>
#include <deque>
#include <vector>

#include "model/mem/dram_address.h"
#include "model/mem/dram_config.h"
#include "model/mem/dram_device.h"
#include "model/mem/latency_histogram.h"
#include "model/mem/memory_level.h"

namespace rtsim {

struct DramCommandCounts {
  uint64_t act = 0, pre = 0, rd = 0, wr = 0, ref = 0, ref_pb = 0;
};

struct BankedDramStats {
  uint64_t reads = 0, writes = 0;            // requests
  uint64_t read_bytes = 0, write_bytes = 0;  // in whole bursts
  uint64_t row_hits = 0;                     // bursts whose row was open
  uint64_t row_misses = 0;                   // bursts that found their bank closed (ACT)
  uint64_t row_conflicts = 0;                // bursts that found another row open (PRE, ACT)
  uint64_t turnarounds = 0;                  // data bus switches between reading and writing
  uint64_t refresh_stall_clocks = 0;         // clocks a rank or bank refreshed with requests queued
  double queued_burst_clocks = 0;            // sum over clocks of bursts queued: occupancy * time
  DramCommandCounts commands;
  LatencyHistogram read_latency;  // core cycles, arrival to data
};

struct DramReadDone {
  uint64_t id;
  Cycle ready;    // core cycle
  Cycle decided;  // the core cycle of its last RD
};

class DramController {
 public:
  // Throws std::invalid_argument for an impossible config (banked_dram_config_problem).
  DramController(const BankedDramConfig& config, double core_ghz);

  // A request of `bytes` at `addr` arriving at core cycle `at` (non-decreasing over calls, and
  // not before a decision already taken).
  // Reads report `id` through advance() when their data is ready; writes report nothing.
  // Returns next_event() of the channels the request joined (the others' is unchanged).
  Cycle enqueue(uint64_t id, uint64_t addr, uint32_t bytes, bool write, Cycle at);
  // The core cycle from which the next decision may be taken (all requests up to it must have
  // been enqueued); kPending when every channel sleeps.
  Cycle next_event() const;
  // Takes every decision that the requests enqueued so far allow up to core cycle `until`
  // (inclusive: requests dated until are all in); completed reads are appended to done in the
  // order of the core cycles their last RD was decided in, then of their channels.
  void advance(Cycle until, std::vector<DramReadDone>& done);

  const BankedDramConfig& config() const { return config_; }
  const BankedDramStats& stats() const { return stats_; }
  uint32_t channels() const { return uint32_t(channels_.size()); }
  const DramChannel& channel(uint32_t i) const { return channels_[i].device; }
  size_t queued() const;                 // bursts waiting, all channels
  Cycle to_core(DramClock clock) const;  // the first core cycle at or after a DRAM clock

 private:
  static constexpr DramClock kNever = ~DramClock(0);
  static constexpr uint8_t kWanted = 1, kHeld = 2;
  // A queue entry: the bursts of one request in one row (a line's two GDDR6 bursts), served by
  // one column command each.
  struct Burst {
    uint32_t request;
    DramAddress a;  // of its next burst
    DramClock arrival;
    uint32_t columns = 1;                         // bursts left, at consecutive columns
    bool needed_act = false, needed_pre = false;  // for it: an ACT, a PRE and an ACT
    bool opened = false;    // its request's ACT opened its row, which stays open for it
    uint32_t bypassed = 0;  // younger row hits served before it
  };
  struct Request {
    uint64_t id = 0;
    Cycle arrival = 0;
    uint32_t bursts = 0;  // left to serve
    DramClock data_end = 0;
    bool write = false;
  };
  struct RankRefresh {
    DramClock due = 0;  // the next refresh's clock
    uint32_t bank = 0;  // per-bank refresh: the bank whose turn it is
  };
  struct Channel {
    explicit Channel(const BankedDramConfig& c) : device(c) {}
    DramChannel device;
    std::vector<Burst> reads, writes;  // arrived, in arrival order
    std::deque<Burst> waiting;         // not arrived yet, or arrived while their queue was full
    std::vector<RankRefresh> refresh;
    DramClock next = kNever;  // the clock of its next decision; kNever: asleep
    bool draining = false;
    bool last_write = false;    // the direction of the last column command
    bool used = false;          // a column command has issued
    std::vector<uint8_t> rows;  // per bank: summarize_rows' flags
    bool rows_valid = false;    // rows is of this step
    DramClock refresh_due = 0;  // the earliest of refresh[].due
  };

  DramClock to_dram(Cycle core) const;   // the first DRAM clock at or after a core cycle
  Cycle core_of(DramClock clock) const;  // the core cycle a DRAM clock falls in
  // One decision at clock t, and the clock of the next one (ch.next).
  void step(Channel& ch, DramClock t, std::vector<DramReadDone>& done);
  // Issues the command due at t, if one is (refresh first); else lowers wake to the clock the
  // first command may issue. dry: issues nothing, only lowers wake (to t at the least).
  bool decide(Channel& ch, DramClock t, DramClock& wake, std::vector<DramReadDone>& done, bool dry);
  // A refresh that is due (ch.refresh_due <= t, refresh on): its PRE or REF, as decide's.
  bool refresh(Channel& ch, DramClock t, DramClock& wake, bool dry);
  bool blocked(const Channel& ch, const Burst& b, DramClock t) const;  // by a due refresh
  bool activated_for(const Channel& ch, const Burst& b) const;  // its open row was opened for it
  // Per bank of the channel, the open row's takers among its queued requests: kWanted (some
  // request hits it), kHeld (it was opened for a request that waits).
  const std::vector<uint8_t>& rows(Channel& ch) const;
  size_t bank_of(const DramAddress& a) const {
    return (size_t(a.rank) * config_.bank_groups + a.group) * config_.banks_per_group + a.bank;
  }
  void mark_opened(Channel& ch, const Burst& b);  // b's ACT: its request's bursts in that row
  // The rank's next bank after a's (bank, then bank group; a division per bank costs the host
  // tens of cycles).
  void next_bank(DramAddress& a) const {
    if (++a.bank == config_.banks_per_group) a.bank = 0, a.group++;
  }
  // FR-FCFS over one queue; returns whether it issued a command, else lowers wake.
  bool schedule(Channel& ch, std::vector<Burst>& queue, bool write, DramClock t, DramClock& wake,
                std::vector<DramReadDone>& done, bool dry);
  void serve_column(Channel& ch, std::vector<Burst>& queue, size_t index, bool write, DramClock t,
                    std::vector<DramReadDone>& done);
  void admit(Channel& ch, DramClock t);  // moves what has arrived by t into its queue, in order

  void set_refresh_due(Channel& ch) const;

  BankedDramConfig config_;
  DramAddressMap map_;
  uint64_t core_rate_, dram_rate_;  // the clock frequencies' ratio, in lowest terms
  std::vector<Channel> channels_;
  std::vector<Request> requests_;
  std::vector<uint32_t> free_requests_;
  BankedDramStats stats_;
};

}  // namespace rtsim
