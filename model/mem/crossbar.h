// The interconnect in front of a shared cache level's slices: a crossbar with one port per
// requester (a unit's last own level, or an instance of the level above; "unit" below) and one
// per slice, each port a link in each direction that moves `bytes_per_cycle` bytes
// a cycle, and `latency` cycles through the switch.
// Timing: a transfer of b bytes from a source port to a destination port takes the source's
// outgoing link from its cycle on, crosses the switch in `latency` cycles, then takes the
// destination's incoming link; it has arrived in the cycle its last byte passes. An unloaded
// transfer of at most bytes_per_cycle bytes therefore takes exactly `latency` cycles. Each link
// keeps the bytes booked in each cycle of a calendar, so transfers may be booked in any order of
// their cycles (responses are known out of order): one is delayed only by transfers already
// booked into its own cycles, never by those of later cycles. Bookings more than
// kCalendarCycles apart share an entry; the earlier cycle then counts as full (conservative;
// counted as calendar_conflicts).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "model/mem/cache.h"
#include "model/mem/memory_level.h"

namespace rtsim {

struct CrossbarConfig {
  uint32_t latency = 0;        // cycles: through the switch, each way
  double bytes_per_cycle = 0;  // bytes/cycle: each port's link in each direction; 0 = no limit
};

std::string crossbar_config_problem(const CrossbarConfig& config);

// How a shared level is split and reached: `slices` slices of size_bytes / slices each (every
// other key of the cache config is per slice), behind a crossbar.
struct SliceLayout {
  uint32_t slices = 1;
  CrossbarConfig crossbar;
};

// Why the layout is impossible for this cache (empty if fine).
std::string slice_layout_problem(const CacheConfig& config, const SliceLayout& layout);

struct LinkStats {
  uint64_t transfers = 0;
  uint64_t bytes = 0;
  uint64_t stall_cycles = 0;        // cycles transfers waited for the link to have room
  uint64_t calendar_conflicts = 0;  // cycles taken as full because a later one held the entry
};

// One direction of one port.
class Link {
 public:
  static constexpr uint32_t kCalendarCycles = 1u << 12;
  static constexpr uint32_t kPrefetchCycles = 8;  // two host cache lines of entries ahead
  explicit Link(double bytes_per_cycle);
  // Books `bytes` from cycle `at` on; returns the cycle the last byte passes.
  Cycle transfer(Cycle at, uint32_t bytes) {
    stats_.transfers++;
    stats_.bytes += bytes;
    if (capacity_ <= 0) return at;
    // The link's next transfers come at later cycles: their entries, cold since the calendar
    // last came round, are asked of the host's memory now (a hint; changes nothing modelled).
    __builtin_prefetch(&calendar_[(at + kPrefetchCycles) & (kCalendarCycles - 1)]);
    // Most transfers fit in their first cycle: the search's first step, without the search. A
    // zero-byte transfer books a sliver (search).
    Slot* slot = entry(at);
    if (slot && bytes > 0 && capacity_ - slot->used >= bytes) {
      slot->used += bytes;
      return at;
    }
    return search(at, bytes);
  }
  const LinkStats& stats() const { return stats_; }

 private:
  struct Slot {
    Cycle cycle = kPending;  // the cycle this entry counts for (kPending: none yet)
    double used = 0;         // bytes booked in it
  };
  // The entry of `cycle` (reset if it held an earlier cycle), or nullptr if a later one holds it.
  Slot* entry(Cycle cycle) {
    Slot& slot = calendar_[cycle & (kCalendarCycles - 1)];
    if (slot.cycle != kPending && slot.cycle > cycle) return nullptr;
    if (slot.cycle != cycle) slot = Slot{cycle, 0};
    return &slot;
  }
  Cycle search(Cycle at, uint32_t bytes);  // books cycle by cycle from `at` (the general case)
  double capacity_;
  std::vector<Slot> calendar_;
  LinkStats stats_;
};

class Crossbar {
 public:
  // Requests carry this many bytes (address and command); writes and data carry their bytes.
  static constexpr uint32_t kRequestBytes = 8;

  Crossbar(const CrossbarConfig& config, uint32_t slices);  // throws std::invalid_argument
  // Gives the crossbar a port for each of `count` units (before any transfer).
  void add_units(uint32_t count);
  // Unit `unit` to slice `slice`: the cycle the transfer has arrived.
  Cycle to_slice(uint32_t unit, uint32_t slice, Cycle at, uint32_t bytes) {
    return modelled_ ? cross(unit_up_[unit], slice_in_[slice], at, bytes) : at;
  }
  // The earliest cycle a transfer from cycle `at` can arrive (with links that have room).
  Cycle earliest(Cycle at) const { return modelled_ ? at + config_.latency : at; }
  Cycle to_unit(uint32_t slice, uint32_t unit, Cycle at, uint32_t bytes) {
    return modelled_ ? cross(slice_out_[slice], unit_down_[unit], at, bytes) : at;
  }

  // Whether there is a crossbar to model (a latency or a bandwidth); without, transfers are free
  // and uncounted.
  bool modelled() const { return modelled_; }
  uint32_t units() const { return uint32_t(unit_up_.size()); }
  uint32_t slices() const { return uint32_t(slice_in_.size()); }
  const Link& unit_up(uint32_t unit) const { return unit_up_[unit]; }      // unit to switch
  const Link& unit_down(uint32_t unit) const { return unit_down_[unit]; }  // switch to unit
  const Link& slice_in(uint32_t slice) const { return slice_in_[slice]; }
  const Link& slice_out(uint32_t slice) const { return slice_out_[slice]; }
  const CrossbarConfig& config() const { return config_; }

 private:
  // From one link, through the switch, onto the other.
  Cycle cross(Link& from, Link& to, Cycle at, uint32_t bytes);
  CrossbarConfig config_;
  bool modelled_;
  std::vector<Link> unit_up_, unit_down_, slice_in_, slice_out_;
};

}  // namespace rtsim
