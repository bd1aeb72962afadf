#include "model/sc/rt_unit_module.h"

#include <algorithm>

namespace rtsim {

RtUnitModule::RtUnitModule(sc_core::sc_module_name name, uint32_t id, const RtCoreConfig& config,
                           const std::vector<MemoryLevelConfig>& levels,
                           const TraversalUnit& traversal, const Clock& clock,
                           uint32_t quantum_cycles, SimControl& control,
                           const TreeletFootprints* footprints, const ShaderConfig& shader)
    : sc_module(name),
      supply("supply"),
      memory("mem", levels, [this] { arm_at(core_.take_data_event()); }),
      clock_(clock),
      quantum_(std::max<uint32_t>(quantum_cycles, 1)),
      control_(control),
      core_(id, config, traversal, memory.cache(), footprints),
      shader_config_(shader) {
  SC_METHOD(run);
}

void RtUnitModule::start_of_simulation() {
  core_.set_supply(&supply->supply());
  if (shader_config_.model != ShaderModel::None) {
    shader_ = std::make_unique<ShaderCore>(
        shader_config_, supply->supply(), memory.cache(),
        [this](Cycle at) { shader_wake_.notify(clock_.delay_to(at)); });
    core_.set_supply(shader_.get());
    wake_or_work_ |= shader_wake_;
  }
  control_.units_running++;
  wake_or_work_ |= wake_;
  wake_or_work_ |= supply->work_event();
}

void RtUnitModule::arm() {
  if (core_.has_event()) arm_at(core_.next_event());
}

// Between runs the core's next event is armed, so data reported for a cycle is the only new
// candidate.
void RtUnitModule::arm_at(Cycle cycle) {
  if (cycle >= armed_) return;  // the pending notification comes first
  armed_ = cycle;
  wake_.notify(clock_.delay_to(cycle));
}

void RtUnitModule::run() {
  try {
    Cycle now = clock_.cycles(sim_now());
    if (armed_ <= now) armed_ = kPending;  // that notification has fired
    uint64_t progress = 0;
    if (!core_.started() || core_.waiting()) progress += core_.poll(now);
    progress += core_.advance(now + quantum_);
    control_.made_progress(progress, now);
    if (core_.finished()) {
      core_.account(core_.stats().last_cycle);
      if (--control_.units_running == 0) sc_core::sc_stop();
      return;  // no next trigger: the unit sleeps for good
    }
    core_.take_data_event();
    arm();
    // With no event, no ray supply to wait for and no read out, nothing can wake the unit:
    // the watchdog reports the stall.
    if (core_.waiting())
      next_trigger(wake_or_work_);
    else
      next_trigger(wake_);
  } catch (...) {
    control_.fail(std::current_exception());
  }
}

}  // namespace rtsim
