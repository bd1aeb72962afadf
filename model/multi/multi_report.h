// The results of `rtsim multi-device` as files and text. Printers only: the figures come from
// run_multi_device() and summarize().
//   report.json   everything: inputs, the device set, hardware, summaries, every frame
//   frames.csv    one row per strategy and frame; devices.csv one row per device too
//   report.md     the strategies side by side (summary and per-frame tables), the chart
//   chart.png     drawn by `rtsim multi-device` with reports/charts/multi_chart.py
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/multi/device_set.h"
#include "model/multi/multi_run.h"
#include "model/multi/multi_summary.h"

namespace rtsim::multi {

constexpr const char* kMultiReportSchema = "rtsim.multi.report/1";

struct ReportInput {
  std::string stream;  // the ray stream's path
  StreamHeader header;
  const DeviceSet* set = nullptr;
  const DeviceConfigs* configs = nullptr;
  const MultiRunResult* result = nullptr;
  std::vector<StrategySummary> summaries;  // one per run, same order
  double host_seconds = 0;
};

nlohmann::ordered_json multi_report_json(const ReportInput& in);
std::string frames_csv(const MultiRunResult& result);
std::string devices_csv(const MultiRunResult& result);
std::string multi_report_markdown(const ReportInput& in, bool with_chart);
// The summary table printed by the command.
std::string format_multi_summary(const ReportInput& in);

// Writes report.json, frames.csv, devices.csv and report.md into dir (created if needed), each
// through a temporary name and a rename.
void write_multi_report(const std::string& dir, const ReportInput& in, bool with_chart);

}  // namespace rtsim::multi
