// Runs a sweep: traces each workload once (OUT/traces/NAME), then one `rtsim run` child per
// workload x point (OUT/points/ID), in parallel on the local cores, printing progress. A point
// is done when its folder holds the request.json of the same request and a report.json, which
// `rtsim run` writes last, through a temporary name: an interrupted sweep (killed, crashed,
// Ctrl-C) resumes by running only the points without one. IDs are the workload's name and a
// hash of everything that determines the result (workload, config file contents, overrides,
// fidelity, the rtsim build), so a changed spec never reuses a stale point. The planning and
// the point runner here are shared with the Slurm engine (reports/sweep_slurm.h).
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
  std::string id, workload, dir, trace_dir;
  const SweepPoint* point = nullptr;
  nlohmann::ordered_json request;  // what request.json records
  bool reused = false;             // done by an earlier run
  bool ok = false;                 // report.json present
  int exit_code = 0;               // of its `rtsim run` (1: verification failed)
  std::string ran_on;              // "local on HOST", "slurm job 12_3 on HOST", or ""
  nlohmann::ordered_json metrics;
};

// Every workload x point of the spec in spec order, with its id, folders and request; those
// finished before come back ok and reused, with their metrics, and any point's where.json
// (ran_on, exit_code) is read. Traces and runs nothing.
std::vector<PointRun> plan_sweep(const SweepSpec& spec, const std::string& output);

// Traces every workload of the spec into OUT/traces/NAME (reusing current traces).
void trace_sweep_workloads(const SweepSpec& spec, const std::string& output, bool quiet);

// The report of a finished point (request.json holds this request, report.json is whole), or
// null.
nlohmann::ordered_json finished_report(const std::string& dir,
                                       const nlohmann::ordered_json& request);

// Readies an unfinished point's folder: removes what an interrupted run left, writes
// request.json, and returns its `rtsim run` argv.
std::vector<std::string> prepare_point(const PointRun& point);

// Writes where.json: where the point runs (engine, host, job), its exit code still null.
void record_where(const PointRun& point, nlohmann::ordered_json where);

// After its run: reads the report (ok, metrics) and records the exit code in where.json.
void finish_point(PointRun& point, int exit_code);

// This machine's short host name.
std::string host_name();

std::vector<PointRun> run_sweep(const SweepSpec& spec, const SweepRunOptions& options);

}  // namespace rtsim::reports
