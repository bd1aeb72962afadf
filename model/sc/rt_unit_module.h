// An RT unit as an sc_module: traversal control and test units (model/sched/rt_core.h) with
// its own cache levels (child module "mem"). The unit reads its first level by a direct call
// (it is part of the unit); the last own level's misses and writes go to the shared levels. Rays
// come from the supply port (dispatcher or treelet queues). One SC_METHOD, no thread per ray: it
// wakes at the cycle of the unit's next event, when the supply announces work, or when the L2
// reports data for a waiting ray; it handles every event before now + quantum (TLM temporal
// decoupling: requests carry the unit's local time as their delay), and sleeps again. A unit whose
// rays all wait on memory sleeps until data arrives. With a shader model the unit's SM
// (model/sched/shader_core.h) stands between the unit and the supply; it wakes the unit when a warp
// slot frees.
#pragma once

#include <memory>

#include <systemc>

#include "model/sc/ray_supply_if.h"
#include "model/sc/tlm_memory.h"
#include "model/sched/rt_core.h"
#include "model/sched/shader_core.h"

namespace rtsim {

class RtUnitModule : public sc_core::sc_module {
 public:
  sc_core::sc_port<RaySupplyIf> supply;
  UnitMemory memory;

  SC_HAS_PROCESS(RtUnitModule);
  RtUnitModule(sc_core::sc_module_name name, uint32_t id, const RtCoreConfig& config,
               const std::vector<MemoryLevelConfig>& levels, const TraversalUnit& traversal,
               const Clock& clock, uint32_t quantum_cycles, SimControl& control,
               const TreeletFootprints* footprints = nullptr, const ShaderConfig& shader = {});

  const RtCore& core() const { return core_; }
  RtCore& core() { return core_; }
  const ShaderCore* shader() const { return shader_.get(); }  // null without a shader model

 private:
  void start_of_simulation() override;
  void run();
  void arm();  // wakes the process at the core's next event
  void arm_at(Cycle cycle);

  Clock clock_;
  uint32_t quantum_;
  SimControl& control_;
  RtCore core_;
  ShaderConfig shader_config_;
  std::unique_ptr<ShaderCore> shader_;
  sc_core::sc_event wake_, shader_wake_;
  Cycle armed_ = kPending;  // the cycle wake_ is notified for (kPending: none)
  sc_core::sc_event_or_list wake_or_work_;
};

}  // namespace rtsim
