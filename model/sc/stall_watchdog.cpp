#include "model/sc/stall_watchdog.h"

#include <sstream>

namespace rtsim {

StallWatchdog::StallWatchdog(sc_core::sc_module_name name, uint64_t stall_cycles,
                             const Clock& clock, SimControl& control,
                             std::function<Cycle()> next_activity,
                             std::function<std::string()> dump)
    : sc_module(name),
      stall_cycles_(stall_cycles),
      clock_(clock),
      control_(control),
      next_activity_(std::move(next_activity)),
      dump_(std::move(dump)) {
  SC_METHOD(run);
}

void StallWatchdog::run() {
  if (control_.units_running == 0 || control_.error) return;
  Cycle now = clock_.cycles(sim_now());
  Cycle deadline = control_.last_progress_cycle + stall_cycles_;
  Cycle promised = next_activity_();
  if (now < deadline || (promised != kPending && promised >= now)) {
    if (now >= deadline) deadline = promised + stall_cycles_;  // slow, not stuck: wait for it
    next_trigger(clock_.time(deadline) - sim_now());
    return;
  }
  std::ostringstream report;
  report << "no progress for " << now - control_.last_progress_cycle
         << " cycles and nothing scheduled to make any (last progress at cycle "
         << control_.last_progress_cycle << ", now cycle " << now << ", " << control_.units_running
         << " units running; sim.stall_cycles = " << stall_cycles_ << "); state:\n"
         << dump_();
  control_.stall_report = report.str();
  sc_core::sc_stop();
}

}  // namespace rtsim
