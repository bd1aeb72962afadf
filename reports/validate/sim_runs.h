// The simulations of `rtsim validate`: each in a forked child (SystemC allows one elaboration
// per process) from rays in memory, two at a time; the parent keeps the scenes and BVHs.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/config/hw_config.h"
#include "model/bvh/bvh_image.h"
#include "traces/ray.h"

namespace rtsim::validation {

// What the checks validate: the config their expected values come from, and the machines they
// build from it as they run. tamper is empty for a real validation; tests set it to break the
// model on purpose (a latency other than the configured one) and see the checks catch it.
struct Target {
  HwConfig config;
  std::function<void(HwConfig&)> tamper;
  HwConfig as_run(HwConfig machine) const {
    if (tamper) tamper(machine);
    return machine;
  }
};

struct SimJob {
  HwConfig config;
  const BvhImage* image = nullptr;
  const std::vector<Ray>* rays = nullptr;
};

// A run's stats: every counter and derived stat by name (StatsRegistry), and the mean latency
// of its measured rays from dispatch to retirement (the per-ray collector, not the units).
class SimFigures {
 public:
  explicit SimFigures(nlohmann::json doc) : doc_(std::move(doc)) {}
  double operator[](const std::string& name) const;  // throws if the run has no such stat
  bool has(const std::string& name) const;
  uint32_t units() const;  // RT units of the run
  // The sum of rtK.<name> over the run's units.
  double units_sum(const std::string& name) const;
  double latency_mean() const { return doc_["latency_mean"].get<double>(); }

 private:
  nlohmann::json doc_;
};

// Runs each job's config as target.as_run() makes it.
std::vector<SimFigures> simulate(const Target& target, const std::vector<SimJob>& jobs);

// A copy of config that only its latencies limit: no port, bank or link bandwidth limits,
// exact event order, no sorting unit, depth-first traversal, no refresh.
HwConfig unloaded(const HwConfig& config);

}  // namespace rtsim::validation
