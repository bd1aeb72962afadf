// The simulation step of `rtsim run`: one fidelity level over a traced stream, writing its
// results into the run folder. At the cycle level (the default) this is `rtsim sim` with every
// ray checked against Embree and a RunCollector beside the stats: stats.json, config.toml and
// the per-pixel buffers (model/sc/sim_report.h). The other levels write fidelity.json and
// config.toml. One call per process (SystemC elaborates once).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/config/hw_config.h"
#include "model/fidelity/level_runner.h"
#include "model/verify/verifier.h"
#include "traces/stream.h"

namespace rtsim::reports {

struct RunJob {
  std::string stream;  // the ray stream
  HwConfig config;
  LevelRequest level;     // Cycle: the full model
  bool verify = true;     // cycle level only
  std::string output;     // run folder (created)
  bool progress = false;  // cycle level: progress on stderr (model/sc/sim_progress.h)
  std::string scene;      // replaces the scene the stream's header names ("": that one)
  std::vector<std::string> ray_types;  // cycle level: only the stream's rays of these types
};

// The mask of RunJob::ray_types over header (every type if none is named); InputError for an
// unknown name or a selection the stream has no rays of (`what` begins the message).
RayTypeMask selected_ray_types(const std::vector<std::string>& names, const StreamHeader& header,
                               const std::string& what, const std::string& stream);

struct RunResult {
  FidelityResult fidelity;            // every level
  nlohmann::ordered_json stats;       // cycle level: the stats document; null otherwise
  nlohmann::ordered_json collected;   // cycle level: RunCollector::to_json(); null otherwise
  std::vector<Mismatch> unexplained;  // cycle level, verified: the first unexplained mismatches
  bool stalled = false;               // the model stopped making progress
  std::string stall_message;
};

RunResult run_job(const RunJob& job);

}  // namespace rtsim::reports
