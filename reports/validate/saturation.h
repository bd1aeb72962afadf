// Runs that saturate one stage of the machine: every other stage set not to limit, and the
// stage's rate measured between a run of N rays and one of 2N, so that the ramp-up and the
// drain, the same in both, cancel.
#pragma once

#include <functional>
#include <string>

#include "model/config/hw_config.h"
#include "reports/validate/sim_runs.h"

namespace rtsim::validation {

constexpr uint32_t kUnlimited = 64;  // test units or issue slots that never limit
constexpr size_t kRays = 16000;      // N

// Two units (most ceilings are per unit), an L1 that holds the whole scene (grid:4096), slots
// refilled one by one and three times as many as `rate` steps a cycle per unit keep busy.
HwConfig ceiling_machine(const HwConfig& preset, double rate);

using Work = std::function<double(const SimFigures&)>;
Work stat(const std::string& name);      // a stat of the run
Work per_unit(const std::string& name);  // rtK.<name>, the mean over the units

// Work over cycles between the run of N rays and the run of 2N.
double steady_rate(const SimFigures& n, const SimFigures& twice, const Work& work);

}  // namespace rtsim::validation
