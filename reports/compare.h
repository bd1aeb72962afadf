// `rtsim compare RUN...`: runs side by side. Each RUN is a run folder (report.json), a `rtsim
// sim` folder (reports/sim_folder.h) or a sweep folder (each finished point, in sweep.json's
// order); every run gets a letter (A, B, ...), its metrics (reports/metrics.h: the flat metrics
// sweeps and suites use, by the same names), each metric's ratio to the first run's, the speed-up
// (the first's cycles over its own) and its bottleneck line. Written as compare.json (schema
// rtsim.compare/1), a terminal table, compare.md and compare.html (compare_pages.cpp).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace rtsim::reports {

constexpr const char* kCompareSchema = "rtsim.compare/1";

// The metrics compared when none is named.
const std::vector<std::string>& default_compare_metrics();

// The comparison of the runs that `runs` name, over `metrics` (default_compare_metrics() if
// empty; type.*.NAME for every ray type). InputError for a folder that is no run, sim or
// sweep folder, a metric that is none, or fewer than two runs.
nlohmann::ordered_json compare_runs(const std::vector<std::string>& runs,
                                    const std::vector<std::string>& metrics);

// The pages of a comparison.
std::string compare_text(const nlohmann::ordered_json& doc);
std::string compare_markdown(const nlohmann::ordered_json& doc);
std::string compare_html(const nlohmann::ordered_json& doc);

}  // namespace rtsim::reports
