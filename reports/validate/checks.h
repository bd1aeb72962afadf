// The checks of `rtsim validate`, by suite; each takes the hardware config under test.
#pragma once

#include <vector>

#include "model/config/hw_config.h"
#include "reports/validate/check.h"

namespace rtsim::validation {

// Closed form (quick): latency ladder, throughput ceilings, DRAM roofline, Little's law.
std::vector<Check> latency_ladder(const HwConfig& config);
std::vector<Check> throughput_ceilings(const HwConfig& config);
std::vector<Check> dram_roofline(const HwConfig& config);
Check littles_law(const HwConfig& config);

}  // namespace rtsim::validation
