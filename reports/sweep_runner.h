// Runs a sweep: traces each workload once (OUT/traces/NAME), then one `rtsim run` child per
// workload x point (OUT/points/ID), in parallel on the local cores, printing progress. A point
// is done when its folder holds the request.json of the same request and a report.json, which
// `rtsim run` writes last, through a temporary name: an interrupted sweep (killed, crashed,
// Ctrl-C) resumes by running only the points without one. IDs are the workload's name and a
// hash of everything that determines the result (workload, config file contents, overrides,
// fidelity), so a changed spec never reuses a stale point.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "reports/sweep_spec.h"

namespace rtsim::reports {

struct SweepRunOptions {
  std::string output;
  uint32_t jobs = 0;  // 0: the spec's [run] jobs, else every local core
  bool quiet = false;
};

struct PointRun {
  std::string id, workload, dir;
  const SweepPoint* point = nullptr;
  bool reused = false;  // done by an earlier, interrupted run
  bool ok = false;      // report.json present
  int exit_code = 0;    // of its `rtsim run` (1: verification failed)
  nlohmann::ordered_json metrics;
};

std::vector<PointRun> run_sweep(const SweepSpec& spec, const SweepRunOptions& options);

}  // namespace rtsim::reports
