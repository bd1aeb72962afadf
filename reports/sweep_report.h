// The results of a sweep: sweep.json (spec, every point's swept values and flat metrics),
// sweep.csv (one row per workload x point), the charts drawn by charts/sweep_charts.py (curves
// of a metric against a swept key, one line per series, and the Pareto chart of cycles
// against on-chip memory) and the pages sweep.html (self-contained) and sweep.md.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "reports/report_writer.h"
#include "reports/sweep_runner.h"

namespace rtsim::reports {

constexpr const char* kSweepSchema = "rtsim.sweep/1";

nlohmann::ordered_json sweep_json(const SweepSpec& spec, const std::vector<PointRun>& points);
std::string sweep_csv(const nlohmann::ordered_json& doc);

// Writes sweep.json, sweep.csv, images/, sweep.html and sweep.md into dir.
ReportOutcome write_sweep_report(nlohmann::ordered_json& doc, const std::string& dir,
                                 const ReportOptions& options);
// `rtsim report SWEEP_DIR`: the same from an existing sweep.json.
ReportOutcome rewrite_sweep_report(const std::string& dir, const ReportOptions& options);

std::string sweep_html(const nlohmann::ordered_json& doc, const std::string& dir);
std::string sweep_markdown(const nlohmann::ordered_json& doc);

}  // namespace rtsim::reports
