// Simulated time in cycles of one clock, and the conversions to and from SystemC time.
#pragma once

#include <cmath>

#include <systemc>

#include "model/mem/memory_level.h"

namespace rtsim {

// SystemC's current time, read inline: sc_core::sc_time_stamp() is a library call, and the
// memory path asks for the time several times per request.
inline const sc_core::sc_time& sim_now() {
  return sc_core::sc_get_curr_simcontext()->time_stamp();
}

class Clock {
 public:
  explicit Clock(const sc_core::sc_time& period = sc_core::sc_time(1.0, sc_core::SC_NS))
      : period_(period), per_unit_(1.0 / double(period.value())) {}
  const sc_core::sc_time& period() const { return period_; }
  // The nearest cycle, in floating point (exact below 2^52 time units; a division, integer or
  // not, is several times slower on the hot path than this multiplication).
  Cycle cycles(const sc_core::sc_time& t) const {
    return Cycle(double(t.value()) * per_unit_ + 0.5);
  }
  sc_core::sc_time time(Cycle c) const { return double(c) * period_; }
  // The TLM delay from now to cycle c (zero if c is not later).
  sc_core::sc_time delay_to(Cycle c) const {
    sc_core::sc_time t = time(c), now = sim_now();
    return t > now ? t - now : sc_core::SC_ZERO_TIME;
  }

 private:
  sc_core::sc_time period_;
  double per_unit_;  // cycles per SystemC time unit
};

}  // namespace rtsim
