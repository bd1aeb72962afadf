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

// What became of the charts a page command asked for, on the terminal: with --no-charts one
// stdout line (unless quiet) and 0; a chart that failed (the script's error, or no Python with
// matplotlib) one stderr line with the reason, `rtsim: charts failed: WHY`, and 1 (the pages are
// written all the same, saying why each chart is missing).
int charts_exit_code(const ReportOutcome& outcome, const ReportOptions& options, bool quiet);

// trace_dir: where the preview pictures are ("" if none).
ReportOutcome write_report(nlohmann::ordered_json& report, const std::string& run_dir,
                           const std::string& trace_dir, const ReportOptions& options);

// Removes what an earlier `rtsim run` wrote into run_dir (results, report, images, and its
// trace unless `keep` lies inside it, as a --from-trace of that trace does), so the folder never
// mixes two runs, even if this one is interrupted. Files rtsim does not write are left alone.
void clear_run_folder(const std::string& run_dir, const std::string& keep);

// Throws InputError naming path and the key if report, read from path, lacks a key the pages
// read directly or holds it of another kind (the rest they read as null when missing).
void require_report_fields(const nlohmann::ordered_json& report, const std::string& path);

// The report.json at path as `rtsim run` writes it (whole, of the schema, with the keys the
// pages read), or null: a sweep's point or a suite's case without one did not finish.
nlohmann::ordered_json whole_report(const std::string& path);

// `rtsim report RUN_DIR`: redraws the charts and rewrites the pages from report.json, or writes
// them for a `rtsim sim` folder (reports/sim_folder.h) from its results.
ReportOutcome rewrite_report(const std::string& run_dir, const ReportOptions& options);

// Removes a report an earlier `rtsim report` wrote into a `rtsim sim` folder (report.json,
// .html, .md), which the new results would contradict.
void clear_sim_folder_report(const std::string& sim_dir);

}  // namespace rtsim::reports
