// The treelet queues (model/sched/treelet_scheduler.h) as an sc_module between the dispatcher
// (port `in`, fresh rays and retirement) and the RT units (export `out`). It notifies
// work_event() whenever a ray is queued or retires, so units that found no ray sleep until
// then. No process of its own.
#pragma once

#include <memory>

#include <systemc>

#include "model/sc/ray_supply_if.h"
#include "model/sched/treelet_scheduler.h"

namespace rtsim {

class TreeletQueueModule : public sc_core::sc_module, public RaySupplyIf {
 public:
  sc_core::sc_port<RaySupplyIf> in;
  sc_core::sc_export<RaySupplyIf> out;

  TreeletQueueModule(sc_core::sc_module_name name, const TreeletQueueConfig& config,
                     uint32_t treelets, std::vector<uint32_t> root_treelets,
                     const RayContextPool& pool, uint32_t state_bytes);

  RaySupply& supply() override;
  const sc_core::sc_event& work_event() const override { return work_; }
  const TreeletScheduler& scheduler() const { return *scheduler_; }
  std::string dump() const;

 private:
  class Notifying;
  void end_of_elaboration() override;

  TreeletQueueConfig config_;
  uint32_t treelets_;
  std::vector<uint32_t> roots_;
  const RayContextPool& pool_;
  uint32_t state_bytes_;
  RaySupply* upstream_ = nullptr;
  std::unique_ptr<TreeletScheduler> scheduler_;
  std::unique_ptr<RaySupply> notifying_;
  sc_core::sc_event work_;
};

}  // namespace rtsim
