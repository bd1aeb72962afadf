// The results of a sweep: sweep.json (spec, every point's swept values and flat metrics),
// sweep.csv (one row per workload x point), the charts drawn by charts/sweep_charts.py (curves
// of a metric against a swept key, one line per series, and the Pareto charts of cycles
// against on-chip memory, area and energy per ray), the objective's pick per workload
// (`[objective]`), and the pages sweep.html (self-contained) and sweep.md.
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

// The objective's pick per workload as text: "WORKLOAD: METRIC V at KEY=VALUE, ... (point ID;
// BOUNDED = V <= BOUND ...)", or why there is none; empty without an objective.
std::vector<std::string> objective_lines(const nlohmann::ordered_json& doc);

std::string sweep_html(const nlohmann::ordered_json& doc, const std::string& dir);
std::string sweep_markdown(const nlohmann::ordered_json& doc);

}  // namespace rtsim::reports
