// Finding a workload from the command line: a spec file or a scene, and the command-line
// overrides of its settings.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "workloads/pipeline/spec.h"

namespace rtsim::pipeline {

// Command-line overrides of a spec; unset fields keep the spec's value. A new scene also makes
// the camera automatic (the spec's lights and material rules stay).
struct SpecOverrides {
  std::optional<uint32_t> frames, width, height;
  std::optional<uint64_t> seed;
  std::optional<std::string> scene;
};
void apply_overrides(WorkloadSpec& spec, const SpecOverrides& overrides);
// From command-line text: resolution "WxH" or "" (InputError if malformed), frames 0 = unset.
SpecOverrides make_overrides(const std::string& resolution, uint32_t frames,
                             std::optional<uint64_t> seed, const std::string& scene);

// A spec file (.toml), or a scene (built-in name or file) with the default spec.
WorkloadSpec load_workload(const std::string& workload);

}  // namespace rtsim::pipeline
