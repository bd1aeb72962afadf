// Stall detection: the simulation must make progress (rays taken, steps, retirements) at least
// once every stall_cycles cycles while units are running, unless it waits for memory that has
// promised data for a known cycle: a slow model (a DRAM of a few bytes a thousand cycles) is
// not a stuck one. With no progress and nothing scheduled (no unit event such as promised data,
// no request queued in the memory hierarchy), or with only activity that is overdue, the watchdog
// stops the run and leaves a report of every module's state (SimControl::stall_report), so a
// stuck model ends with a clear error instead of a hang. It wakes only at the cycle the current
// deadline expires (last progress + stall_cycles, or the promised cycle + stall_cycles), never
// on idle cycles in between.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>

#include <systemc>

#include "model/sc/clock.h"
#include "model/sc/ray_supply_if.h"

namespace rtsim {

// A run that stopped making progress, or ran out of events with rays unfinished: exit code 1
// (app/cli_main.cpp), also from a forked child (model/sc/fork_run.h).
class SimStallError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class StallWatchdog : public sc_core::sc_module {
 public:
  SC_HAS_PROCESS(StallWatchdog);
  // next_activity: the earliest cycle something is scheduled: a unit's event (the data a read
  // was promised, a test unit's result) or a request the memory will serve (kPending: none);
  // dump: the state report.
  StallWatchdog(sc_core::sc_module_name name, uint64_t stall_cycles, const Clock& clock,
                SimControl& control, std::function<Cycle()> next_activity,
                std::function<std::string()> dump);

 private:
  void run();

  uint64_t stall_cycles_;
  Clock clock_;
  SimControl& control_;
  std::function<Cycle()> next_activity_;
  std::function<std::string()> dump_;
};

}  // namespace rtsim
