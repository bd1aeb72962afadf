// report.md of a run: the same sections as report.html, shorter, with links to the PNGs.
#include <fmt/core.h>

#include "reports/page_util.h"
#include "reports/report_pages.h"

namespace rtsim::reports {
namespace {

using Json = nlohmann::ordered_json;
constexpr int kInt = int(Style::Integer), kReal = int(Style::Real), kPct = int(Style::Percent);

std::string passes(const Json& r) {
  std::string out =
      "| pass | ray type | rays | budget per frame | skipped | why |\n"
      "|---|---|---|---|---|---|\n";
  for (const Json& p : r["workload"]["passes"])
    out += fmt::format("| {} | {} | {} | {} | {} | {} |\n", p["pass"].get<std::string>(),
                       p["ray_type"].get<std::string>(), p["rays"].get<uint64_t>(),
                       p["budget_per_frame"].get<uint64_t>(),
                       p["skipped"].get<bool>() ? "yes" : "no", p["reason"].get<std::string>());
  return out;
}

std::string verification(const Json& r) {
  const Json& v = r["verification"];
  if (v["skipped"].get<bool>()) return "Skipped: " + v["reason"].get<std::string>() + ".\n";
  return fmt::format(
      "**{}**: {} rays checked against Embree, {} agree, {} mismatches, "
      "{} unexplained.\n",
      v["passed"].get<bool>() ? "PASSED" : "FAILED", v["rays"].get<uint64_t>(),
      v["agree"].get<uint64_t>(), v["mismatches"].get<uint64_t>(),
      v["unexplained"].get<uint64_t>());
}

std::string images(const Json& r) {
  std::string out;
  for (const Json& image : r["images"]) {
    std::string title = image["title"].get<std::string>();
    if (image["available"].get<bool>())
      out += fmt::format("### {}\n\n![{}]({})\n\n{}\n\n", title, title,
                         image["file"].get<std::string>(), image["caption"].get<std::string>());
    else
      out += fmt::format("### {}\n\nNot available: {}.\n\n", title,
                         image["reason"].get<std::string>());
  }
  return out;
}

}  // namespace

std::string report_markdown(const Json& r) {
  std::string out = fmt::format(
      "# rtsim report: {} on {}\n\n{} · `{}` · full report: "
      "report.html, data: report.json\n\n",
      r["workload"]["name"].get<std::string>(), r["hardware"]["name"].get<std::string>(),
      r["generator"].get<std::string>(), r["command"].get<std::string>());
  out += "## Summary\n\n" +
         markdown_rows(r, {{"fidelity level", "timing.level", Style::Text},
                           {"rays", "timing.rays", Style::Integer},
                           {"cycles", "timing.cycles", Style::Integer},
                           {"MRays/s", "timing.mrays_per_second", Style::Real},
                           {"DRAM bytes per ray", "bandwidth.dram_bytes_per_ray", Style::Real},
                           {"L1 hit rate", "bandwidth.l1_hit_rate", Style::Percent},
                           {"L2 hit rate", "bandwidth.l2_hit_rate", Style::Percent}});
  out +=
      "\n## Workload\n\n" + markdown_rows(r, {{"scene", "workload.scene", Style::Text},
                                              {"triangles", "workload.triangles", Style::Integer},
                                              {"width", "workload.width", Style::Integer},
                                              {"height", "workload.height", Style::Integer},
                                              {"frames", "workload.frames", Style::Integer},
                                              {"rays", "workload.rays", Style::Integer}});
  out += "\n" + markdown_type_table(r, "workload.rays_per_type", {{"rays", "", kInt}}) + "\n" +
         passes(r);
  out += "\n## Hardware config\n\n" +
         markdown_rows(r, {{"preset", "hardware.name", Style::Text},
                           {"config file", "hardware.config_file", Style::Text},
                           {"clock (GHz)", "hardware.clock_ghz", Style::Real},
                           {"RT units", "hardware.rt_units", Style::Integer},
                           {"traversal", "hardware.mode", Style::Text},
                           {"L1 bytes (per unit)", "hardware.l1.size_bytes", Style::Integer},
                           {"L2 bytes", "hardware.l2.size_bytes", Style::Integer},
                           {"BVH", "hardware.bvh", Style::Text},
                           {"on-chip bytes", "hardware.on_chip_bytes", Style::Integer}});
  out += "\n## Timing\n\n" +
         markdown_rows(r, {{"time model", "timing.time_model", Style::Text},
                           {"cycles", "timing.cycles", Style::Integer},
                           {"cycles, 95% interval (±)", "timing.cycles_ci95", Style::Integer},
                           {"clock (GHz)", "timing.clock_ghz", Style::Real},
                           {"MRays/s at the clock", "timing.mrays_per_second", Style::Real}});
  out += "\n" + markdown_type_table(r, "latency.by_type",
                                    {{"p50", "p50", kInt},
                                     {"p95", "p95", kInt},
                                     {"p99", "p99", kInt},
                                     {"mean", "mean", kReal}});
  out += "\n## Bandwidth\n\n" +
         markdown_rows(r, {{"L1 bytes per ray", "bandwidth.l1_bytes_per_ray", Style::Real},
                           {"L2 bytes per ray", "bandwidth.l2_bytes_per_ray", Style::Real},
                           {"DRAM bytes per ray", "bandwidth.dram_bytes_per_ray", Style::Real},
                           {"DRAM utilisation", "bandwidth.dram_utilisation", Style::Percent}});
  out += "\n" + markdown_type_table(r, "hit_rates.by_type",
                                    {{"L1 hit rate", "l1", kPct}, {"L2 hit rate", "l2", kPct}});
  out += "\n## Coherence\n\n" +
         markdown_type_table(r, "coherence.by_type",
                             {{"nodes/ray", "nodes_per_ray", kReal},
                              {"triangles/ray", "triangles_per_ray", kReal},
                              {"stack spills/ray", "stack_spills_per_ray", kReal}});
  out += "\n## Verification\n\n" + verification(r);
  out += "\n## Pictures and charts\n\n" + images(r);
  return out;
}

}  // namespace rtsim::reports
