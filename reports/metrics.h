// The flat metrics of a run, by name, read from its report.json: what sweeps tabulate and
// chart and what regression suites compare. Names: cycles, cycles_ci95, mrays_per_second,
// rays, dram_bytes, dram_bytes_per_ray, l1_bytes_per_ray, l2_bytes_per_ray, l1_hit_rate,
// l2_hit_rate, dram_utilisation, nodes_per_ray, triangles_per_ray, stack_spills_per_ray,
// on_chip_bytes, energy_nj_per_ray, mrays_per_joule, power_w, area_mm2, sram_area_mm2,
// unexplained, host_seconds, and per ray type type.T.rays, type.T.dram_bytes_per_ray,
// type.T.l1_hit_rate, type.T.l2_hit_rate, type.T.nodes_per_ray, type.T.latency_mean,
// type.T.latency_p50, type.T.latency_p99, type.T.dynamic_energy_nj_per_ray. A metric the run's
// fidelity level does not model is null.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "reports/page_util.h"

namespace rtsim::reports {

nlohmann::ordered_json flat_metrics(const nlohmann::ordered_json& report);

// Why `name` is no metric of flat_metrics (empty if it is one); type.*.NAME stands for NAME of
// every ray type.
std::string metric_name_problem(const std::string& name);

// Whether a larger value is better ("higher"), worse ("lower"), or neither ("either").
std::string metric_direction(const std::string& name);

// How a page shows the metric: hit rates as percentages, counts whole, the rest as reals.
Style metric_style(const std::string& name);

// The metric names of `names` for these reports, in order: type.*.NAME becomes NAME of every
// ray type any report has. InputError (`what`: "... --metric X: problem") for a name that is no
// metric.
std::vector<std::string> expand_metric_names(const std::vector<std::string>& names,
                                             const std::vector<nlohmann::ordered_json>& reports,
                                             const std::string& what);

}  // namespace rtsim::reports
