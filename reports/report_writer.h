// Writes a run's report into its folder: report.json (the data), images/ (the preview and
// density pictures copied from the trace, heatmaps and charts drawn by run_charts.py),
// report.html (self-contained) and report.md. Every file goes through a temporary name.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace rtsim::reports {

struct ReportOptions {
  bool charts = true;  // false: no Python; the pages say the charts were skipped
  bool pages = true;   // false: report.json only (sweeps, regression suites)
};

struct ReportOutcome {
  bool charts_ok = true;
  std::string message;  // why charts are missing
};

// trace_dir: where the preview pictures are ("" if none).
ReportOutcome write_report(nlohmann::ordered_json& report, const std::string& run_dir,
                           const std::string& trace_dir, const ReportOptions& options);

// `rtsim report RUN_DIR`: redraws the charts and rewrites the pages from report.json.
ReportOutcome rewrite_report(const std::string& run_dir, const ReportOptions& options);

}  // namespace rtsim::reports
