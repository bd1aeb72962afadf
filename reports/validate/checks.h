// The checks of `rtsim validate`, by suite; each takes the hardware config under test.
#pragma once

#include <vector>

#include "reports/validate/check.h"
#include "reports/validate/sim_runs.h"

namespace rtsim::validation {

// Closed form (quick): latency ladder, throughput ceilings, DRAM roofline, Little's law.
std::vector<Check> latency_ladder(const Target& target);
std::vector<Check> throughput_ceilings(const Target& target);
std::vector<Check> dram_roofline(const Target& target);
Check littles_law(const Target& target);

}  // namespace rtsim::validation
