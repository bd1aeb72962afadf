#include "model/sc/stall_watchdog.h"

#include <sstream>

namespace rtsim {

StallWatchdog::StallWatchdog(sc_core::sc_module_name name, uint64_t stall_cycles,
                             const Clock& clock, SimControl& control,
                             std::function<std::string()> dump)
    : sc_module(name),
      stall_cycles_(stall_cycles),
      clock_(clock),
      control_(control),
      dump_(std::move(dump)) {
  SC_METHOD(run);
}

void StallWatchdog::run() {
  if (control_.units_running == 0 || control_.error) return;
  Cycle now = clock_.cycles(sc_core::sc_time_stamp());
  Cycle deadline = control_.last_progress_cycle + stall_cycles_;
  if (now < deadline) {
    next_trigger(clock_.time(deadline) - sc_core::sc_time_stamp());
    return;
  }
  std::ostringstream report;
  report << "no progress for " << stall_cycles_ << " cycles (last progress at cycle "
         << control_.last_progress_cycle << ", now cycle " << now << ", " << control_.units_running
         << " units running); state:\n"
         << dump_();
  control_.stall_report = report.str();
  sc_core::sc_stop();
}

}  // namespace rtsim
