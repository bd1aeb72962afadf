// The comparison of a regression run with its baseline: every case's metrics under the suite's
// tolerances, the verification of every case, the delta table, JUnit XML for CI systems, and
// the baseline file itself (BASELINE/baseline.json, schema rtsim.regress.baseline/1).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "reports/regress_suite.h"

namespace rtsim::reports {

constexpr const char* kBaselineSchema = "rtsim.regress.baseline/1";

struct CaseOutcome {
  std::string name;
  bool ran = false;                // its run left a report
  int exit_code = 0;               // of its `rtsim run`
  nlohmann::ordered_json metrics;  // flat_metrics of its report
  double seconds = 0;
};

struct MetricCheck {
  std::string case_name, metric, direction;
  nlohmann::ordered_json baseline, current;
  double allowed = 0;  // deviation allowed, in the metric's unit
  std::string status;  // ok, improved, regressed, changed, missing
  bool failed() const {
    return status == "regressed" || status == "changed" || status == "missing";
  }
};

struct RegressResult {
  std::vector<CaseOutcome> cases;
  std::vector<MetricCheck> checks;
  std::vector<std::string> case_failures;  // "case: why" (run failed, verification failed)
  bool failed() const;
};

nlohmann::ordered_json baseline_json(const RegressSuite& suite,
                                     const std::vector<CaseOutcome>& cases);

RegressResult compare_with_baseline(const RegressSuite& suite, std::vector<CaseOutcome> cases,
                                    const nlohmann::ordered_json& baseline);

std::string delta_table(const RegressResult& result, bool markdown);
std::string junit_xml(const RegressSuite& suite, const RegressResult& result);
nlohmann::ordered_json regress_json(const RegressSuite& suite, const RegressResult& result);

}  // namespace rtsim::reports
