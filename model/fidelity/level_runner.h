// Runs any fidelity level by name, in this process or in a forked child (SystemC allows one
// elaboration per process, so a command that runs several timed levels forks for each).
#pragma once

#include <string>

#include "model/bvh/two_level.h"
#include "model/config/hw_config.h"
#include "model/fidelity/fidelity_result.h"
#include "model/fidelity/sample_plan.h"

namespace rtsim {

struct LevelRequest {
  FidelityLevel level = FidelityLevel::Cycle;
  SamplingConfig sampling;  // sampled level only
};

FidelityResult run_level(const LevelRequest& request, const HwConfig& config, BvhView image,
                         const std::string& stream);

// The same in a forked child; the parent's state (scene, BVH) is shared copy-on-write.
FidelityResult run_level_in_child(const LevelRequest& request, const HwConfig& config,
                                  BvhView image, const std::string& stream);

}  // namespace rtsim
