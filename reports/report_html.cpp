// report.html of a run: summary, workload, hardware config, timing, bandwidth, DRAM, energy,
// coherence, verification, pictures and charts, in that order.
#include <fmt/core.h>

#include "reports/page_util.h"
#include "reports/report_pages.h"

namespace rtsim::reports {
namespace {

using Json = nlohmann::ordered_json;
constexpr int kInt = int(Style::Integer), kReal = int(Style::Real);

std::string section(const char* id, const char* title, const std::string& body) {
  return fmt::format("<section id=\"{}\">\n<h2>{}</h2>\n{}</section>\n", id, title, body);
}

std::string workload(const Json& r) {
  std::string out = html_rows(r, workload_rows());
  out += "<h3>Rays per type</h3>\n" +
         html_type_table(r, "workload.rays_per_type", {{"rays", "", kInt}});
  if (r["workload"]["passes"].empty())
    return out + "<h3>Passes of the hybrid pipeline</h3>\n<p class=\"na\">" +
           html_escape(kNoPasses) + "</p>\n";
  out +=
      "<h3>Passes of the hybrid pipeline</h3>\n<table>\n<tr><th>pass</th><th>ray type</th>"
      "<th>rays</th><th>budget per frame</th><th>skipped</th><th>why</th></tr>\n";
  const Json& passes = r["workload"]["passes"];
  for (size_t i = 0; i < passes.size(); ++i) {
    std::string p = "workload.passes." + std::to_string(i);
    out += "<tr><th>" + html_escape(passes[i]["pass"].get<std::string>()) + "</th>" +
           html_cell(r, p + ".ray_type", Style::Text) + html_cell(r, p + ".rays", Style::Integer) +
           html_cell(r, p + ".budget_per_frame", Style::Integer) +
           html_cell(r, p + ".skipped", Style::Text) + html_cell(r, p + ".reason", Style::Text) +
           "</tr>\n";
  }
  return out + "</table>\n";
}

std::string hardware(const Json& r) {
  std::string out = html_rows(r, hardware_rows());
  const Json& sets = r["hardware"]["sets"];
  if (!sets.empty()) out += "<p>Overrides: <code>" + html_escape(sets.dump()) + "</code></p>\n";
  return out + "<details><summary>Every key, resolved</summary><pre>" +
         html_escape(r["hardware"]["resolved"].dump(2)) + "</pre></details>\n";
}

std::string bandwidth(const Json& r) {
  std::string out = html_rows(r, bandwidth_rows());
  return out + "<h3>Per ray type</h3>\n" +
         html_type_table(r, "bandwidth.by_type",
                         {{"L1 line bytes/ray", "l1_bytes_per_ray", kReal},
                          {"L2 line bytes/ray", "l2_bytes_per_ray", kReal},
                          {"DRAM bytes/ray", "dram_bytes_per_ray", kReal}});
}

std::string dram(const Json& r) {
  std::string out = html_rows(r, dram_rows());
  if (r["dram"]["by_channel"].empty()) return out;
  return out + "<h3>Per channel</h3>\n" +
         html_type_table(r, "dram.by_channel",
                         {{"data bus utilisation", "utilisation", int(Style::Percent)},
                          {"busy DRAM clocks", "busy_clocks", kInt}},
                         "channel");
}

std::string energy(const Json& r) {
  if (r["energy"].is_null())
    return "<p class=\"na\">n/a: the energy model counts the events of a cycle-level run.</p>\n";
  return html_rows(r, energy_rows()) + "<h3>Per structure</h3>\n" +
         html_type_table(r, "energy.structures", energy_structure_columns(), "structure") +
         "<h3>Dynamic energy per ray type</h3>\n" +
         html_type_table(r, "energy.by_type", {{"nJ/ray", "dynamic_nj_per_ray", kReal}});
}

std::string coherence(const Json& r) {
  std::string out = html_rows(
      r, {{"nodes per ray", "coherence.nodes_per_ray", Style::Real},
          {"triangles per ray", "coherence.triangles_per_ray", Style::Real},
          {"stack spills per ray", "coherence.stack_spills_per_ray", Style::Real},
          {"SIMD efficiency (packets)", "coherence.simd_efficiency", Style::Percent},
          {"distinct nodes per warp step", "coherence.distinct_nodes_per_warp_step", Style::Real},
          {"rays per treelet visit", "coherence.rays_per_treelet_visit", Style::Real},
          {"mean rays queued (treelets)", "coherence.treelet_queue_mean_rays", Style::Real}});
  if (!at_key(r, "coherence.instances_per_ray").is_null()) out += html_rows(r, two_level_rows());
  return out + html_type_table(r, "coherence.by_type",
                               {{"nodes/ray", "nodes_per_ray", kReal},
                                {"triangles/ray", "triangles_per_ray", kReal},
                                {"stack spills/ray", "stack_spills_per_ray", kReal}});
}

std::string verification(const Json& r) {
  const Json& v = r["verification"];
  if (v["skipped"].get<bool>())
    return "<p>Skipped: " + html_escape(v["reason"].get<std::string>()) + ".</p>\n";
  bool passed = v["passed"].get<bool>();
  std::string out = fmt::format(
      "<p class=\"{}\">{}: every ray checked against Embree "
      "(robust mode); unexplained mismatches must be zero.</p>\n",
      passed ? "pass" : "fail", passed ? "PASSED" : "FAILED");
  out += html_rows(r, {{"rays checked", "verification.rays", Style::Integer},
                       {"agree", "verification.agree", Style::Integer},
                       {"mismatches", "verification.mismatches", Style::Integer},
                       {"unexplained", "verification.unexplained", Style::Integer}});
  if (!v["by_class"].empty())
    out += "<h3>Mismatches by class</h3>\n" +
           html_type_table(r, "verification.by_class", {{"rays", "", kInt}}, "class");
  return out;
}

std::string latency(const Json& r) {
  return html_type_table(r, "latency.by_type",
                         {{"p50", "p50", kInt},
                          {"p95", "p95", kInt},
                          {"p99", "p99", kInt},
                          {"mean", "mean", kReal},
                          {"max", "max", kInt}});
}

}  // namespace

std::string report_html(const Json& r, const std::string& run_dir) {
  std::string title =
      fmt::format("rtsim report: {} on {}", r["workload"]["name"].get<std::string>(),
                  r["hardware"]["name"].get<std::string>());
  std::string out = html_head(title);
  out += "<h1>" + html_escape(title) + "</h1>\n<p class=\"meta\">" +
         html_escape(r["generator"].get<std::string>()) + " &middot; <code>" +
         html_escape(r["command"].get<std::string>()) + "</code> &middot; data: report.json</p>\n";
  out +=
      "<nav><a href=\"#summary\">Summary</a><a href=\"#workload\">Workload</a><a "
      "href=\"#hardware\">Hardware</a><a href=\"#timing\">Timing</a><a "
      "href=\"#bandwidth\">Bandwidth</a><a href=\"#dram\">DRAM</a><a "
      "href=\"#energy\">Energy</a><a href=\"#coherence\">Coherence</a><a "
      "href=\"#verification\">Verification</a><a href=\"#pictures\">Pictures</a><a "
      "href=\"#charts\">Charts</a></nav>\n";
  out += section("summary", "Summary", html_rows(r, summary_rows()));
  out += section("workload", "Workload", workload(r));
  out += section("hardware", "Hardware config", hardware(r));
  out += section(
      "timing", "Timing",
      html_rows(r, timing_rows()) + "<h3>Latency per ray type (cycles)</h3>\n" + latency(r));
  out += section("bandwidth", "Bandwidth", bandwidth(r));
  out += section("dram", "DRAM", dram(r));
  out += section("energy", "Energy and area", energy(r));
  out += section("coherence", "Coherence", coherence(r));
  out += section("verification", "Verification", verification(r));
  out += section("pictures", "Pictures", html_figures(r, run_dir, {"picture", "heatmap"}));
  out += section("charts", "Charts", html_figures(r, run_dir, {"chart"}));
  return out + html_tail();
}

}  // namespace rtsim::reports
