// The ray sorting unit (model/sched/ray_sorter.h) as an sc_module between the dispatcher (port
// `in`) and the RT units (export `out`). No process: a unit's take is a function call at the
// unit's time. Its buffer has contexts of its own, so it never makes a unit wait for rays.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include <systemc>

#include "model/sc/ray_supply_if.h"
#include "model/sched/ray_sorter.h"

namespace rtsim {

class RaySorterModule : public sc_core::sc_module, public RaySupplyIf {
 public:
  sc_core::sc_port<RaySupplyIf> in;
  sc_core::sc_export<RaySupplyIf> out;

  RaySorterModule(sc_core::sc_module_name name, const SortConfig& config,
                  const SceneBounds& bounds);

  RaySupply& supply() override { return *sorter_; }
  const sc_core::sc_event& work_event() const override { return never_; }
  const RaySorter& sorter() const { return *sorter_; }
  // Called with every ray as it leaves the sorter (RaySorter::watch).
  void on_leave(std::function<void(const RayContext&)> watcher) { watcher_ = std::move(watcher); }
  std::string dump() const;

 private:
  void end_of_elaboration() override;

  SortConfig config_;
  SceneBounds bounds_;
  std::unique_ptr<RaySorter> sorter_;
  std::function<void(const RayContext&)> watcher_;
  sc_core::sc_event never_;
};

}  // namespace rtsim
