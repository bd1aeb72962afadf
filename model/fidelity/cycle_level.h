// Fidelity level 3, the full cycle-approximate model (model/sc/rt_simulator.h) over every ray,
// reported in the common FidelityResult shape. SystemC allows one elaboration per process:
// callers that run several levels in one command run each in a child (model/sc/fork_run.h).
#pragma once

#include <string>

#include "model/bvh/two_level.h"
#include "model/config/hw_config.h"
#include "model/fidelity/fidelity_result.h"
#include "model/sc/rt_simulator.h"

namespace rtsim {

// The result of a finished simulation (host times left at 0 for the caller's HostTimer).
FidelityResult cycle_level_result(const RtSimulator& sim);

// Simulates every ray of the stream (no verification, no pixel buffers).
FidelityResult run_cycle_level(const HwConfig& config, BvhView image, const std::string& stream);

}  // namespace rtsim
