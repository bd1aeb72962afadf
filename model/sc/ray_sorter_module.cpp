#include "model/sc/ray_sorter_module.h"

namespace rtsim {

RaySorterModule::RaySorterModule(sc_core::sc_module_name name, const SortConfig& config,
                                 const SceneBounds& bounds)
    : sc_module(name), in("in"), out("out"), config_(config), bounds_(bounds), never_("never") {
  out.bind(*this);
}

void RaySorterModule::end_of_elaboration() {
  sorter_ = std::make_unique<RaySorter>(config_, bounds_, in->supply());
  sorter_->watch(watcher_);
}

std::string RaySorterModule::dump() const {
  return std::string(name()) + ": " + std::to_string(sorter_->held()) + " rays in the buffer\n";
}

}  // namespace rtsim
