// A sweep spec (TOML): hardware points (a grid, the product of value lists per config key, or
// an explicit list of points) over one or more workloads, on a base config. Format and
// examples: reports/README.md, reports/examples/. Unknown keys are errors naming the line;
// config keys are checked by loading each point's config before anything runs.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/fidelity/sample_plan.h"
#include "reports/trace_step.h"

namespace rtsim::reports {

struct SweepWorkload {
  std::string name;  // label in tables and charts
  TraceRequest trace;
};

struct SweepPoint {
  nlohmann::ordered_json values;  // config key -> value, in spec order
  std::vector<std::string> sets;  // the same as --set KEY=VALUE (TOML syntax values)
  std::vector<uint32_t> lines;    // the spec's line of each of them
};

struct SweepChart {
  std::string x, y, series;  // y may hold "*" for every ray type; series: key or "workload"
};

// The point to pick: the least (or most) of a metric among the points within budgets on
// other metrics ("least energy per ray under 10 mm² of SRAM").
struct SweepObjective {
  std::string metric;  // empty: no objective
  bool maximise = false;
  std::vector<std::pair<std::string, double>> at_most, at_least;  // metric, bound
};

// The most points (workloads x configs) a sweep takes unless asked for more (`rtsim sweep
// --max-points`): a grid is counted before it is expanded, so a mistyped one is refused at once.
// A point costs a few kilobytes of memory before it runs, so even --max-points is capped.
constexpr uint64_t kDefaultMaxSweepPoints = 10000;
constexpr uint64_t kMostSweepPoints = 1000000;
// The most config keys a sweep sets (a grid, or its points together): far more than a config
// has, and few enough that expanding the spec stays quick.
constexpr size_t kMostSweptKeys = 1000;

struct SweepSpec {
  std::string file, name, description;
  uint64_t max_points = kDefaultMaxSweepPoints;  // the limit it was read under
  std::string config;                            // base hardware config file ("" = defaults)
  std::vector<std::string> sets;                 // applied to every point, before the point's own
  std::vector<SweepWorkload> workloads;
  std::vector<std::string> keys;  // swept keys, in spec order
  std::vector<SweepPoint> points;
  std::string fidelity = "cycle";
  SamplingConfig sampling;
  bool verify = true;
  uint32_t jobs = 0;               // parallel runs; 0: every local core
  std::vector<SweepChart> charts;  // empty: curves of cycles and DRAM bytes per swept key
  SweepObjective objective;
};

SweepSpec read_sweep_spec(const std::string& path, uint64_t max_points = kDefaultMaxSweepPoints);

}  // namespace rtsim::reports
