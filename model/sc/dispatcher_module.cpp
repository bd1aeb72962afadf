#include "model/sc/dispatcher_module.h"

namespace rtsim {

DispatcherModule::DispatcherModule(sc_core::sc_module_name name, const DispatchConfig& config,
                                   RaySource& source, RayContextPool& pool,
                                   RayRetireListener* listener)
    : sc_module(name), out("out"), dispatcher_(config, source, pool, listener), never_("never") {
  out.bind(*this);
}

}  // namespace rtsim
