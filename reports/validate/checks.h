// The checks of `rtsim validate`, by suite; each takes the hardware config under test.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "model/mem/dram_controller.h"
#include "reports/validate/check.h"
#include "reports/validate/sim_runs.h"

namespace rtsim::validation {

// Advances the controller from `from` until `reads` reads are done; throws if they are not
// within 100M cycles (a controller that stopped answering).
void drain(DramController& controller, size_t reads, Cycle from, std::vector<DramReadDone>& done);

// Closed form (quick): latency ladder, throughput ceilings, DRAM roofline, Little's law.
std::vector<Check> latency_ladder(const Target& target);
std::vector<Check> throughput_ceilings(const Target& target);
std::vector<Check> dram_roofline(const Target& target);
std::vector<Check> port_rooflines(const Target& target);
Check littles_law(const Target& target);
Check dram_loaded_latency(const Target& target);

// Published results (full suite): on the shared scenes, skipped where they are missing.
std::vector<Check> published_checks(const Target& target,
                                    const std::function<void(const std::string&)>& progress);
// The path of a shared scene by name (conference, sibenik, sponza, bunny, dragon).
std::string shared_scene_path(const std::string& name);

// Bracketing runs for the costs the model leaves out or simplifies (full suite).
std::vector<Check> sensitivity_checks(const Target& target);

// The sampled level against the full model on pica and Sponza, over seeds (full suite).
std::vector<Check> sampling_checks(const Target& target,
                                   const std::function<void(const std::string&)>& progress);

// GPU-like presets against their vendors' figures (full suite).
std::vector<Check> preset_checks(const Target& target,
                                 const std::function<void(const std::string&)>& progress);

}  // namespace rtsim::validation
