#include "reports/metrics.h"

#include "reports/page_util.h"

namespace rtsim::reports {

using Json = nlohmann::ordered_json;

Json flat_metrics(const Json& r) {
  Json m;
  auto put = [&](const std::string& name, const std::string& key) { m[name] = at_key(r, key); };
  put("cycles", "timing.cycles");
  put("cycles_ci95", "timing.cycles_ci95");
  put("mrays_per_second", "timing.mrays_per_second");
  put("rays", "timing.rays");
  put("dram_bytes", "bandwidth.dram_bytes");
  put("dram_bytes_per_ray", "bandwidth.dram_bytes_per_ray");
  put("l1_bytes_per_ray", "bandwidth.l1_bytes_per_ray");
  put("l2_bytes_per_ray", "bandwidth.l2_bytes_per_ray");
  put("l1_hit_rate", "bandwidth.l1_hit_rate");
  put("l2_hit_rate", "bandwidth.l2_hit_rate");
  put("dram_utilisation", "bandwidth.dram_utilisation");
  put("nodes_per_ray", "coherence.nodes_per_ray");
  put("triangles_per_ray", "coherence.triangles_per_ray");
  put("stack_spills_per_ray", "coherence.stack_spills_per_ray");
  put("on_chip_bytes", "hardware.on_chip_bytes");
  put("unexplained", "verification.unexplained");
  put("host_seconds", "timing.host_seconds");
  for (const auto& [type, rays] : r["workload"]["rays_per_type"].items()) {
    std::string p = "type." + type + ".";
    m[p + "rays"] = rays;
    put(p + "dram_bytes_per_ray", "bandwidth.by_type." + type + ".dram_bytes_per_ray");
    put(p + "l1_hit_rate", "hit_rates.by_type." + type + ".l1");
    put(p + "l2_hit_rate", "hit_rates.by_type." + type + ".l2");
    put(p + "nodes_per_ray", "coherence.by_type." + type + ".nodes_per_ray");
    put(p + "latency_mean", "latency.by_type." + type + ".mean");
    put(p + "latency_p50", "latency.by_type." + type + ".p50");
    put(p + "latency_p99", "latency.by_type." + type + ".p99");
  }
  return m;
}

std::string metric_direction(const std::string& name) {
  auto ends = [&](const std::string& suffix) {
    return name.size() >= suffix.size() &&
           name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  if (ends("hit_rate") || ends("mrays_per_second")) return "higher";
  if (ends("cycles") || ends("bytes") || ends("per_ray") || ends("unexplained") ||
      ends("latency_mean") || ends("latency_p50") || ends("latency_p99"))
    return "lower";
  return "either";
}

}  // namespace rtsim::reports
