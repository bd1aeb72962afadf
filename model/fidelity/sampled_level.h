// Fidelity level 4, sampled simulation: the full cycle-approximate model runs only on the
// windows of a SamplePlan (sample_plan.h), each preceded by its warm-up rays, one window after
// another in one simulation so the machine never drains between them. Measurement, per
// window: its rays' costs (counters, cache hits, DRAM bytes, latency) from the retire
// listener, and its time as the cycles between the moments the count of retired rays reaches
// the window's first and its last ray (in steady state that is the window's share of the
// machine's throughput). Each stratum's total is its window's scaled by the stratum's length
// over the window's; totals add up over strata, and one mean ray latency is added for filling
// and draining the pipeline. Intervals: stratified.h.
#pragma once

#include <string>

#include "model/bvh/two_level.h"
#include "model/config/hw_config.h"
#include "model/fidelity/fidelity_result.h"
#include "model/fidelity/sample_plan.h"

namespace rtsim {

// Runs the model on the sampled windows of the stream in this process (SystemC: once per
// process). Throws InputError if the stream is too short for the rate.
FidelityResult run_sampled_level(const HwConfig& config, BvhView image, const std::string& stream,
                                 const SamplingConfig& sampling);

}  // namespace rtsim
