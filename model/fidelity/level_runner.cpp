#include "model/fidelity/level_runner.h"

#include <fmt/format.h>

#include "model/fidelity/cache_level.h"
#include "model/fidelity/cycle_level.h"
#include "model/fidelity/functional_level.h"
#include "model/fidelity/sampled_level.h"
#include "model/fidelity/scaled_level.h"
#include "model/sc/fork_run.h"
#include "traces/error.h"

namespace rtsim {

FidelityResult run_level(const LevelRequest& request, const HwConfig& config, BvhView image,
                         const std::string& stream) {
  // The warmed method traces the absent units through one filter level into one shared level
  // (l2_warming.h): a unit level and one shared level.
  if (request.level == FidelityLevel::Sampled && request.sampling.method == SampleMethod::Warmed) {
    if (!two_level_problem(config, "").empty())
      throw InputError(fmt::format(
          "--sample-method warmed: it warms one shared level behind a unit level; this "
          "machine has {} levels ({} first): use --sample-method scale-model or windows",
          config.memory.size(), first_level(config).name));
  }
  switch (request.level) {
    case FidelityLevel::Functional: return run_functional_level(image, stream);
    case FidelityLevel::CacheLevel: return run_cache_level(config, image, stream);
    case FidelityLevel::Cycle: return run_cycle_level(config, image, stream);
    case FidelityLevel::Sampled: break;
  }
  if (request.sampling.method == SampleMethod::Windows)
    return run_sampled_level(config, image, stream, request.sampling);
  return run_scaled_level(config, image, stream, request.sampling);
}

FidelityResult run_level_in_child(const LevelRequest& request, const HwConfig& config,
                                  BvhView image, const std::string& stream) {
  std::string text =
      run_in_child([&] { return run_level(request, config, image, stream).to_json().dump(); });
  return FidelityResult::from_json(nlohmann::json::parse(text));
}

}  // namespace rtsim
