// sweep.html (self-contained) and sweep.md: the spec, every point with its main metrics, and
// the charts.
#include <fmt/core.h>

#include "reports/page_util.h"
#include "reports/report_pages.h"
#include "reports/sweep_report.h"

namespace rtsim::reports {
namespace {

using Json = nlohmann::ordered_json;

struct Metric {
  const char* name;
  const char* title;
  Style style;
};
const Metric kMetrics[] = {{"cycles", "cycles", Style::Integer},
                           {"mrays_per_second", "MRays/s", Style::Real},
                           {"dram_bytes_per_ray", "DRAM B/ray", Style::Real},
                           {"l1_hit_rate", "L1 hit rate", Style::Percent},
                           {"l2_hit_rate", "L2 hit rate", Style::Percent},
                           {"on_chip_bytes", "on-chip bytes", Style::Integer},
                           {"energy_nj_per_ray", "nJ/ray", Style::Real},
                           {"area_mm2", "area mm²", Style::Real},
                           {"unexplained", "unexplained", Style::Integer}};

std::string pareto_cost(const std::string& metric) {
  if (metric == "area_mm2") return "area on chip (test units, registers and SRAM, model/energy)";
  if (metric == "energy_nj_per_ray") return "energy per ray (dynamic and static, model/energy)";
  return "on-chip memory (caches, ray stacks, the treelet ray buffer and the sorting buffer)";
}

std::string title_of(const Json& doc) {
  return "rtsim sweep: " + doc["spec"]["name"].get<std::string>();
}

Json figures_doc(const Json& doc) {
  Json images = Json::array();
  for (const Json& c : doc["charts"])
    images.push_back(
        {{"id", c["id"]},
         {"file", c["file"]},
         {"kind", "chart"},
         {"title", c["title"]},
         {"caption", c["kind"] == "pareto"
                         ? fmt::format("Each point's cycles against its {}; the line joins "
                                       "the Pareto-optimal points of each workload.",
                                       pareto_cost(c["x"].get<std::string>()))
                         : fmt::format("{} against {}, one line per {}.", c["y"].get<std::string>(),
                                       c["x"].get<std::string>(), c["series"].get<std::string>())},
         {"available", c["available"]},
         {"reason", c["reason"]}});
  return {{"images", images}};
}

}  // namespace

std::string sweep_html(const Json& doc, const std::string& dir) {
  std::string out = html_head(title_of(doc)) + "<h1>" + html_escape(title_of(doc)) + "</h1>\n";
  const Json& spec = doc["spec"];
  out += "<p class=\"meta\">" + html_escape(doc["generator"].get<std::string>()) + " &middot; " +
         html_escape(spec["file"].get<std::string>()) +
         " &middot; data: sweep.json, sweep.csv</p>\n";
  if (!spec["description"].get<std::string>().empty())
    out += "<p>" + html_escape(spec["description"].get<std::string>()) + "</p>\n";
  out += "<section id=\"spec\">\n<h2>Spec</h2>\n" +
         html_rows(doc, {{"base config", "spec.config", Style::Text},
                         {"fidelity", "spec.fidelity", Style::Text},
                         {"verify", "spec.verify", Style::Text}}) +
         "<p>Swept keys: <code>" + html_escape(spec["keys"].dump()) + "</code>; workloads: <code>" +
         html_escape(spec["workloads"].dump()) + "</code></p>\n</section>\n";
  out += "<section id=\"points\">\n<h2>Points</h2>\n<table>\n<tr><th>workload</th>";
  for (const Json& k : spec["keys"]) out += "<th>" + html_escape(k.get<std::string>()) + "</th>";
  out += "<th>status</th><th>ran on</th>";
  for (const Metric& m : kMetrics) out += std::string("<th>") + m.title + "</th>";
  out += "</tr>\n";
  const Json& points = doc["points"];
  for (size_t i = 0; i < points.size(); ++i) {
    std::string p = "points." + std::to_string(i);
    out += "<tr><th>" + html_escape(points[i]["workload"].get<std::string>()) + "</th>";
    for (const Json& k : spec["keys"]) {
      const Json& value = swept_value(points[i]["values"], k.get<std::string>());
      out += "<td>" + html_escape(show(value, Style::Real)) + "</td>";
    }
    out += html_cell(doc, p + ".status", Style::Text);
    out += "<td>" + html_escape(points[i].value("ran_on", "")) + "</td>";
    for (const Metric& m : kMetrics) out += html_cell(doc, p + ".metrics." + m.name, m.style);
    out += "</tr>\n";
  }
  out += "</table>\n</section>\n";
  std::vector<std::string> best = objective_lines(doc);
  if (!best.empty()) {
    out += "<section id=\"objective\">\n<h2>Objective</h2>\n<ul>\n";
    for (const std::string& line : best) out += "<li>" + html_escape(line) + "</li>\n";
    out += "</ul>\n</section>\n";
  }
  out += "<section id=\"charts\">\n<h2>Charts</h2>\n" +
         html_figures(figures_doc(doc), dir, {"chart"}) + "</section>\n";
  return out + html_tail();
}

std::string sweep_markdown(const Json& doc) {
  const Json& spec = doc["spec"];
  std::string out = "# " + title_of(doc) + "\n\n" + spec["description"].get<std::string>() +
                    "\n\nBase config: " + spec["config"].get<std::string>() + ", fidelity " +
                    spec["fidelity"].get<std::string>() +
                    ". Data: sweep.json, sweep.csv; full "
                    "page: sweep.html.\n\n| workload |";
  for (const Json& k : spec["keys"]) out += " " + k.get<std::string>() + " |";
  out += " status | ran on |";
  for (const Metric& m : kMetrics) out += std::string(" ") + m.title + " |";
  out += "\n|---|";
  for (size_t i = 0; i < spec["keys"].size() + 2 + std::size(kMetrics); ++i) out += "---|";
  out += "\n";
  for (const Json& p : doc["points"]) {
    out += "| " + p["workload"].get<std::string>() + " |";
    for (const Json& k : spec["keys"])
      out += " " + show(swept_value(p["values"], k.get<std::string>()), Style::Real) + " |";
    out += " " + p["status"].get<std::string>() + " | " + p.value("ran_on", "") + " |";
    for (const Metric& m : kMetrics)
      out += " " + show(at_key(p, std::string("metrics.") + m.name), m.style) + " |";
    out += "\n";
  }
  out += "\n";
  std::vector<std::string> best = objective_lines(doc);
  if (!best.empty()) {
    out += "## Objective\n\n";
    for (const std::string& line : best) out += "- " + line + "\n";
    out += "\n";
  }
  for (const Json& c : doc["charts"])
    out += c["available"].get<bool>()
               ? fmt::format("## {}\n\n![{}]({})\n\n", c["title"].get<std::string>(),
                             c["title"].get<std::string>(), c["file"].get<std::string>())
               : fmt::format("## {}\n\nNot available: {}.\n\n", c["title"].get<std::string>(),
                             c["reason"].get<std::string>());
  return out;
}

}  // namespace rtsim::reports
