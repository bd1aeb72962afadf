// The results of a simulation run as files: stats JSON (schema in model/SIM.md), the
// resolved config, and per-pixel buffers (raw float32) for heatmaps. Printers only: the
// counters come from RtSimulator::report and SimStatsCollector, ratios are derived here.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/sc/rt_simulator.h"
#include "model/verify/verifier.h"
#include "traces/stream.h"

namespace rtsim {

struct SimRunInfo {
  std::string stream;   // the ray stream's path (or a description of generated rays)
  StreamHeader header;  // scene, workload, pixel grid
  std::optional<BvhView> bvh;
  const VerifyReport* verify = nullptr;  // null: verification skipped
  double host_seconds = 0;               // wall time of the run, the Embree check included
  std::vector<std::string> ray_types;    // the stream's ray types simulated; empty: all
};

constexpr const char* kSimStatsSchema = "rtsim.sim.stats/1";

// The stats document. Everything but "host" is a function of the inputs and the config.
nlohmann::ordered_json sim_stats_json(const RtSimulator& sim, const StatsRegistry& stats,
                                      const SimRunInfo& info);

// Writes stats.json, config.toml and the pixel buffers into dir (created if needed), each
// through a temporary name and a rename. Returns the stats document.
nlohmann::ordered_json write_sim_results(const std::string& dir, const RtSimulator& sim,
                                         const SimRunInfo& info);

// The files write_sim_results may write into dir, for the check that none is an input.
std::vector<std::string> sim_result_files(const std::string& dir);

// Writes bytes to path.tmp-PID and renames it to path; InputError naming path and the
// system's reason (e.g. "No space left on device") if that fails.
void write_file_atomic(const std::string& path, const void* data, size_t size);
void write_file_atomic(const std::string& path, const std::string& bytes);

}  // namespace rtsim
