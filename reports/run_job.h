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

namespace rtsim::reports {

struct RunJob {
  std::string stream;  // the ray stream
  HwConfig config;
  LevelRequest level;     // Cycle: the full model
  bool verify = true;     // cycle level only
  std::string output;     // run folder (created)
  bool progress = false;  // cycle level: progress on stderr (model/sc/sim_progress.h)
};

struct RunResult {
  FidelityResult fidelity;           // every level
  nlohmann::ordered_json stats;      // cycle level: the stats document; null otherwise
  nlohmann::ordered_json collected;  // cycle level: RunCollector::to_json(); null otherwise
  bool stalled = false;              // the model stopped making progress
  std::string stall_message;
};

RunResult run_job(const RunJob& job);

}  // namespace rtsim::reports
