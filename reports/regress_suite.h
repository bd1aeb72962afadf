// A regression suite (TOML): cases (a workload on a hardware config) and per-metric
// tolerances. Format and example: reports/README.md, reports/examples/smoke-suite.toml.
#pragma once

#include <string>
#include <vector>

#include "model/fidelity/sample_plan.h"
#include "reports/trace_step.h"

namespace rtsim::reports {

struct RegressCase {
  std::string name;
  TraceRequest trace;
  std::string config;             // hardware config file ("" = defaults)
  std::vector<std::string> sets;  // --set overrides
  std::string fidelity = "cycle";
  SamplingConfig sampling;
};

// Allowed deviation from the baseline: max(relative x |baseline|, absolute). direction:
// "lower" (a larger value is a regression), "higher" (a smaller value is), "either" (any
// deviation is); "" takes the metric's own (metrics.h).
struct Tolerance {
  std::string metric;  // a metric name; "type.*.NAME" means NAME of every ray type
  double relative = 0, absolute = 0;
  std::string direction;
};

struct RegressSuite {
  std::string file, name, description;
  std::vector<RegressCase> cases;
  std::vector<Tolerance> tolerances;
  bool verify = true;  // a case whose verification finds an unexplained mismatch fails
};

RegressSuite read_regress_suite(const std::string& path);

}  // namespace rtsim::reports
