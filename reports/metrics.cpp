#include "reports/metrics.h"

#include <algorithm>

#include "reports/page_util.h"
#include "traces/error.h"
#include "traces/ray.h"

namespace rtsim::reports {

using Json = nlohmann::ordered_json;

namespace {

// Each metric of a run and where report.json holds it.
struct MetricKey {
  const char* name;
  const char* key;
};
constexpr MetricKey kRunMetrics[] = {
    {"cycles", "timing.cycles"},
    {"cycles_ci95", "timing.cycles_ci95"},
    {"mrays_per_second", "timing.mrays_per_second"},
    {"rays", "timing.rays"},
    {"dram_bytes", "bandwidth.dram_bytes"},
    {"dram_bytes_per_ray", "bandwidth.dram_bytes_per_ray"},
    {"l1_bytes_per_ray", "bandwidth.l1_bytes_per_ray"},
    {"l2_bytes_per_ray", "bandwidth.l2_bytes_per_ray"},
    {"l1_hit_rate", "bandwidth.l1_hit_rate"},
    {"l2_hit_rate", "bandwidth.l2_hit_rate"},
    {"dram_utilisation", "bandwidth.dram_utilisation"},
    {"nodes_per_ray", "coherence.nodes_per_ray"},
    {"triangles_per_ray", "coherence.triangles_per_ray"},
    {"stack_spills_per_ray", "coherence.stack_spills_per_ray"},
    {"on_chip_bytes", "hardware.on_chip_bytes"},
    {"energy_nj_per_ray", "energy.nj_per_ray"},
    {"mrays_per_joule", "energy.mrays_per_joule"},
    {"power_w", "energy.power_w"},
    {"area_mm2", "energy.area_mm2"},
    {"sram_area_mm2", "energy.sram_area_mm2"},
    {"unexplained", "verification.unexplained"},
    {"host_seconds", "timing.host_seconds"},
};
// Per ray type T: type.T.NAME, at the key with T in place of %.
constexpr MetricKey kTypeMetrics[] = {
    {"dram_bytes_per_ray", "bandwidth.by_type.%.dram_bytes_per_ray"},
    {"l1_hit_rate", "hit_rates.by_type.%.l1"},
    {"l2_hit_rate", "hit_rates.by_type.%.l2"},
    {"nodes_per_ray", "coherence.by_type.%.nodes_per_ray"},
    {"latency_mean", "latency.by_type.%.mean"},
    {"latency_p50", "latency.by_type.%.p50"},
    {"latency_p99", "latency.by_type.%.p99"},
    {"dynamic_energy_nj_per_ray", "energy.by_type.%.dynamic_nj_per_ray"},
};

std::string with_type(const char* key, const std::string& type) {
  std::string k = key;
  return k.replace(k.find('%'), 1, type);
}

}  // namespace

Json flat_metrics(const Json& r) {
  Json m;
  for (const MetricKey& k : kRunMetrics) m[k.name] = at_key(r, k.key);
  const Json& types = at_key(r, "workload.rays_per_type");  // any report.json: null-safe reads
  if (!types.is_object()) return m;
  for (const auto& [type, rays] : types.items()) {
    std::string p = "type." + type + ".";
    m[p + "rays"] = rays;
    for (const MetricKey& k : kTypeMetrics) m[p + k.name] = at_key(r, with_type(k.key, type));
  }
  return m;
}

std::string metric_name_problem(const std::string& name) {
  for (const MetricKey& k : kRunMetrics)
    if (name == k.name) return {};
  std::string names, type_names = "rays";
  for (const MetricKey& k : kRunMetrics) names += std::string(names.empty() ? "" : ", ") + k.name;
  for (const MetricKey& k : kTypeMetrics) type_names += std::string(", ") + k.name;
  if (name.rfind("type.", 0) == 0) {
    size_t dot = name.find('.', 5);
    std::string type = name.substr(5, dot == std::string::npos ? std::string::npos : dot - 5);
    std::string rest = dot == std::string::npos ? "" : name.substr(dot + 1);
    if (type != "*" && !ray_type_from_name(type))
      return "unknown ray type '" + type + "' in metric '" + name + "'";
    if (rest == "rays") return {};
    for (const MetricKey& k : kTypeMetrics)
      if (rest == k.name) return {};
    return "unknown metric '" + name +
           "' (per ray type: type.TYPE.NAME or type.*.NAME, NAME one of " + type_names + ")";
  }
  return "unknown metric '" + name + "' (metrics: " + names + "; per ray type: type.*.NAME)";
}

std::string metric_direction(const std::string& name) {
  auto ends = [&](const std::string& suffix) {
    return name.size() >= suffix.size() &&
           name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  if (ends("hit_rate") || ends("mrays_per_second") || ends("mrays_per_joule")) return "higher";
  if (ends("cycles") || ends("bytes") || ends("per_ray") || ends("unexplained") ||
      ends("latency_mean") || ends("latency_p50") || ends("latency_p99") || ends("power_w") ||
      ends("mm2"))
    return "lower";
  return "either";
}

Style metric_style(const std::string& name) {
  auto ends = [&](const std::string& suffix) {
    return name.size() >= suffix.size() &&
           name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  if (ends("hit_rate") || ends("utilisation")) return Style::Percent;
  if (ends("cycles") || ends("rays") || ends("unexplained") || name == "dram_bytes" ||
      name == "on_chip_bytes")
    return Style::Integer;
  return Style::Real;
}

std::vector<std::string> expand_metric_names(const std::vector<std::string>& names,
                                             const std::vector<Json>& reports,
                                             const std::string& what) {
  std::vector<std::string> out;
  for (const std::string& name : names) {
    std::string problem = metric_name_problem(name);
    if (!problem.empty()) throw InputError(what + " " + name + ": " + problem);
    if (name.rfind("type.*.", 0) != 0) {
      out.push_back(name);
      continue;
    }
    std::vector<std::string> types;
    for (const Json& r : reports)
      for (const auto& [type, rays] : at_key(r, "workload.rays_per_type").items())
        if (std::find(types.begin(), types.end(), type) == types.end()) types.push_back(type);
    for (const std::string& type : types) out.push_back("type." + type + name.substr(6));
  }
  return out;
}

}  // namespace rtsim::reports
