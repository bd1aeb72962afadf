// The report of one run as a JSON document (schema rtsim.report/1): every number the HTML and
// Markdown pages show comes from here, under the key the page names beside it. Sections:
// workload, hardware, fidelity, timing, bandwidth, coherence, verification, latency, hit_rates,
// time (where the time went) and images (pictures and charts, with their files and captions).
// At the cycle level everything is filled; faster fidelity levels leave what they do not model
// null, and the pages say so.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/config/hw_config.h"
#include "reports/run_job.h"
#include "reports/trace_step.h"

namespace rtsim::reports {

constexpr const char* kReportSchema = "rtsim.report/1";

struct ReportInputs {
  const TraceOutcome* trace = nullptr;
  const HwConfig* config = nullptr;
  std::string config_file;
  std::vector<std::string> sets;
  const RunResult* run = nullptr;
  std::string command;  // the command line that made the run
};

nlohmann::ordered_json build_report(const ReportInputs& in);

// Bytes of on-chip memory the config spends on caches and ray stacks:
// rt.count x (L1 + ray slots x stack entries x entry bytes) + L2.
double on_chip_bytes(const HwConfig& config);

// The pictures and charts of a report, with availability decided by what the run produced.
nlohmann::ordered_json report_images(const nlohmann::ordered_json& report, bool has_preview,
                                     bool has_pixels);

}  // namespace rtsim::reports
