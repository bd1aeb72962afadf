// The time estimate of the cache-level fidelity: a roofline over the resources of the RT
// hardware. Each resource gives a lower bound on the cycles the run needs (work / throughput),
// the largest one is the estimate, plus one mean ray latency for filling and draining the
// pipeline. Contention, queueing and MSHR limits are not modelled; the cycle level has them.
// Resources, per RT unit: traversal control (steps / issue_per_cycle), the ray-box and
// ray-triangle unit pools (issues / count), the warp slots (Little's law: the sum of each
// warp's occupancy, i.e. its slowest ray's latency, over the warp slots); shared: the
// dispatcher (rays / rays_per_cycle) and the DRAM bus (bytes / bytes_per_cycle).
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "model/config/hw_config.h"

namespace rtsim {

struct UnitWork {
  uint64_t steps = 0;             // node and leaf steps
  uint64_t box_issues = 0;        // ray-box unit issues (ceil(boxes / issue_width) per node)
  uint64_t triangle_issues = 0;   // ray-triangle unit issues
  uint64_t transform_issues = 0;  // instance transform unit issues (two levels)
  double warp_cycles = 0;         // sum over the unit's warps of their slowest ray's latency
};

struct AnalyticInputs {
  std::vector<UnitWork> units;
  uint64_t rays = 0;
  uint64_t dram_bytes = 0;
  double mean_latency = 0;  // cycles
};

struct AnalyticTime {
  double cycles = 0;
  std::string bound;  // the resource that binds ("rt0.control", "dram", ...)
  std::vector<std::pair<std::string, double>> bounds;  // every resource's lower bound
};

AnalyticTime analytic_time(const HwConfig& config, const AnalyticInputs& inputs);

}  // namespace rtsim
