// report.md of a run: the same sections as report.html, shorter, with links to the PNGs.
#include <fmt/core.h>

#include "reports/page_util.h"
#include "reports/report_pages.h"
#include "traces/text_table.h"

namespace rtsim::reports {
namespace {

using Json = nlohmann::ordered_json;
constexpr int kInt = int(Style::Integer), kReal = int(Style::Real), kPct = int(Style::Percent);

std::string passes(const Json& r) {
  if (r["workload"]["passes"].empty()) return std::string(kNoPasses) + "\n";
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
      v["passed"].get<bool>() ? "PASSED" : "FAILED", whole_number(v["rays"].get<uint64_t>()),
      whole_number(v["agree"].get<uint64_t>()), whole_number(v["mismatches"].get<uint64_t>()),
      whole_number(v["unexplained"].get<uint64_t>()));
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
  out += "## Summary\n\n" + markdown_rows(r, summary_rows());
  out += "\n## Workload\n\n" + markdown_rows(r, workload_rows());
  out += "\n" + markdown_type_table(r, "workload.rays_per_type", {{"rays", "", kInt}}) + "\n" +
         passes(r);
  out += "\n## Hardware config\n\n" + markdown_rows(r, hardware_rows());
  out += "\n## Timing\n\n" + markdown_rows(r, timing_rows());
  out += "\n" + markdown_type_table(r, "latency.by_type",
                                    {{"p50", "p50", kInt},
                                     {"p95", "p95", kInt},
                                     {"p99", "p99", kInt},
                                     {"mean", "mean", kReal}});
  out += "\n## Bandwidth\n\n" + markdown_rows(r, bandwidth_rows());
  out += "\n" + markdown_type_table(r, "hit_rates.by_type",
                                    {{"L1 hit rate", "l1", kPct}, {"L2 hit rate", "l2", kPct}});
  out += "\n## DRAM\n\n" + markdown_rows(r, dram_rows());
  if (!r["dram"]["by_channel"].empty())
    out += "\n" + markdown_type_table(r, "dram.by_channel",
                                      {{"data bus utilisation", "utilisation", kPct}}, "channel");
  out += "\n## Energy and area\n\n" + markdown_rows(r, energy_rows());
  if (!r["energy"].is_null())
    out +=
        "\n" + markdown_type_table(r, "energy.structures", energy_structure_columns(), "structure");
  if (!at_key(r, "coherence.instances_per_ray").is_null())
    out += "\n## Two BVH levels\n\n" + markdown_rows(r, two_level_rows());
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
