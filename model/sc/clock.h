// Simulated time in cycles of one clock, and the conversions to and from SystemC time.
#pragma once

#include <cmath>

#include <systemc>

#include "model/mem/memory_level.h"

namespace rtsim {

struct Clock {
  sc_core::sc_time period{1.0, sc_core::SC_NS};  // 1 GHz

  // The nearest cycle, in floating point (exact below 2^53 time units; a 64-bit integer
  // division is several times slower on the hot path).
  Cycle cycles(const sc_core::sc_time& t) const {
    return Cycle(double(t.value()) / double(period.value()) + 0.5);
  }
  sc_core::sc_time time(Cycle c) const { return double(c) * period; }
  // The TLM delay from now to cycle c (zero if c is not later).
  sc_core::sc_time delay_to(Cycle c) const {
    sc_core::sc_time t = time(c), now = sc_core::sc_time_stamp();
    return t > now ? t - now : sc_core::SC_ZERO_TIME;
  }
};

}  // namespace rtsim
