// The ray dispatcher (model/sched/dispatcher.h) as an sc_module: exports the ray supply that
// RT units (or the treelet queues) bind to. No process: a unit's request is a function call
// at the unit's time, and the dispatcher's port bandwidth is a reservation.
#pragma once

#include <systemc>

#include "model/sc/ray_supply_if.h"
#include "model/sched/dispatcher.h"

namespace rtsim {

class DispatcherModule : public sc_core::sc_module, public RaySupplyIf {
 public:
  sc_core::sc_export<RaySupplyIf> out;

  DispatcherModule(sc_core::sc_module_name name, const DispatchConfig& config, RaySource& source,
                   RayContextPool& pool, RayRetireListener* listener);

  RaySupply& supply() override { return dispatcher_; }
  const sc_core::sc_event& work_event() const override { return never_; }
  const RayDispatcher& dispatcher() const { return dispatcher_; }
  RayDispatcher& dispatcher() { return dispatcher_; }

 private:
  RayDispatcher dispatcher_;
  sc_core::sc_event never_;  // rays never come later than asked: the pool fits every slot
};

}  // namespace rtsim
