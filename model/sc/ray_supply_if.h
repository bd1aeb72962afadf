// The SystemC face of a ray supply (model/sched/ray_supply.h): the ray dispatcher and the
// treelet queues export it, RT units reach it through an sc_port. work_event() is notified
// whenever rays may have become available to a unit that found none (a ray was postponed or
// retired), so an idle unit sleeps until then instead of polling.
#pragma once

#include <systemc>

#include "model/sched/ray_supply.h"

namespace rtsim {

class RaySupplyIf : public virtual sc_core::sc_interface {
 public:
  virtual RaySupply& supply() = 0;
  virtual const sc_core::sc_event& work_event() const = 0;
};

// Shared by the modules of one simulation: progress for the stall watchdog, the first error,
// and how many units are still running.
struct SimControl {
  uint64_t progress = 0;          // rays taken, steps and retirements, all units
  Cycle last_progress_cycle = 0;  // SystemC cycle of the latest progress
  uint32_t units_running = 0;
  std::exception_ptr error;  // the first exception a process threw
  std::string stall_report;  // set by the watchdog when it stops a stalled run

  void made_progress(uint64_t amount, Cycle now) {
    if (amount == 0) return;
    progress += amount;
    if (now > last_progress_cycle) last_progress_cycle = now;
  }
  void fail(std::exception_ptr e) {
    if (!error) error = e;
    sc_core::sc_stop();
  }
};

}  // namespace rtsim
