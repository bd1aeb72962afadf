#include "model/sc/rt_unit_module.h"

#include <algorithm>

namespace rtsim {

RtUnitModule::RtUnitModule(sc_core::sc_module_name name, uint32_t id, const RtCoreConfig& config,
                           const CacheConfig& l1_config, const TraversalUnit& traversal,
                           const Clock& clock, uint32_t quantum_cycles, bool direct_l1,
                           const CacheStats* l2_stats, SimControl& control)
    : sc_module(name),
      mem("mem"),
      supply("supply"),
      l1("l1", l1_config, clock),
      clock_(clock),
      quantum_(std::max<uint32_t>(quantum_cycles, 1)),
      control_(control),
      port_([this](auto& trans, auto& delay) { mem->b_transport(trans, delay); }, clock),
      direct_(l1.direct(), port_),
      core_(id, config, traversal, direct_l1 ? static_cast<RayMemory&>(direct_) : port_,
            MemoryProbe{&l1.cache().stats(), l2_stats}) {
  mem.bind(l1.in);
  SC_METHOD(run);
}

void RtUnitModule::start_of_simulation() {
  core_.set_supply(&supply->supply());
  control_.units_running++;
}

void RtUnitModule::run() {
  try {
    Cycle now = clock_.cycles(sc_core::sc_time_stamp());
    uint64_t progress = 0;
    if (!core_.started() || core_.waiting()) progress += core_.poll(now);
    progress += core_.advance(now + quantum_);
    control_.made_progress(progress, now);
    if (core_.finished()) {
      core_.account(core_.stats().last_cycle);
      if (--control_.units_running == 0) sc_core::sc_stop();
      return;  // no next trigger: the unit sleeps for good
    }
    if (core_.has_event()) {
      sc_core::sc_time delay = clock_.time(core_.next_event()) - sc_core::sc_time_stamp();
      if (core_.waiting())
        next_trigger(delay, supply->work_event());
      else
        next_trigger(delay);
    } else if (core_.waiting()) {
      next_trigger(supply->work_event());
    }
    // Otherwise nothing can wake the unit: the watchdog reports the stall.
  } catch (...) {
    control_.fail(std::current_exception());
  }
}

}  // namespace rtsim
