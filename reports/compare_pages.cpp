// The pages of `rtsim compare` (compare.h): the terminal table, compare.md and compare.html.
// Rows are metrics, columns runs: each run's value and, from the second run on, its ratio to
// the first's. The HTML cells carry their compare.json key and raw value, as the report's do.
#include <algorithm>

#include <fmt/core.h>

#include "reports/compare.h"
#include "reports/metrics.h"
#include "reports/page_util.h"
#include "reports/report_pages.h"

namespace rtsim::reports {
namespace {

using Json = nlohmann::ordered_json;

// A ratio as 0.812x: three decimals, whole from 100 on, three significant digits below 0.1.
std::string times(const Json& ratio) {
  if (!ratio.is_number()) return "n/a";
  double r = ratio.get<double>();
  return fmt::format(r >= 100 ? "{:.0f}x" : r >= 0.1 ? "{:.3f}x" : "{:.3g}x", r);
}

// "better" or "worse" than the first run for a ratio of the metric, or "" (neither, or equal).
std::string verdict(const std::string& metric, const Json& ratio) {
  if (!ratio.is_number() || ratio.get<double>() == 1) return "";
  std::string direction = metric == "speedup" ? "higher" : metric_direction(metric);
  if (direction == "either") return "";
  return (ratio.get<double>() > 1) == (direction == "higher") ? "better" : "worse";
}

// One row of the table: a title, then per run its value and its ratio to the first.
struct Line {
  std::string title;
  std::vector<std::string> cells;
};

std::vector<Line> lines(const Json& doc) {
  const Json& runs = doc["runs"];
  std::vector<Line> out;
  Line head{"metric", {}}, speedup{"speed-up (A's cycles / cycles)", {}};
  for (size_t i = 0; i < runs.size(); ++i) {
    std::string label = runs[i]["label"].get<std::string>();
    head.cells.push_back(label);
    speedup.cells.push_back(times(runs[i]["speedup"]));
    if (i) head.cells.push_back(label + "/A");
    if (i) speedup.cells.push_back("");
  }
  out.push_back(head);
  out.push_back(speedup);
  for (const Json& m : doc["metrics"]) {
    std::string name = m.get<std::string>();
    Line line{name, {}};
    for (size_t i = 0; i < runs.size(); ++i) {
      line.cells.push_back(show(runs[i]["metrics"][name], metric_style(name)));
      if (i) line.cells.push_back(times(runs[i]["ratios"][name]));
    }
    out.push_back(line);
  }
  return out;
}

// A number cell with its compare.json key and raw value; kind "better" or "worse" colours it.
std::string cell(const std::string& key, const Json& value, const std::string& shown,
                 const std::string& kind) {
  std::string cls = value.is_null()    ? " class=\"na\""
                    : kind == "better" ? " class=\"pass\""
                    : kind == "worse"  ? " class=\"fail\""
                                       : "";
  return fmt::format("<td data-key=\"{}\" data-value=\"{}\"{}>{}</td>", html_escape(key),
                     html_escape(value.dump()), cls, html_escape(shown));
}

// The run's --set overrides, "KEY=VALUE, ...", or "none".
std::string sets_of(const Json& run) {
  std::string out;
  for (const Json& set : run["sets"]) out += (out.empty() ? "" : ", ") + set.get<std::string>();
  return out.empty() ? "none" : out;
}

std::string run_line(const Json& run) {
  std::string sets = sets_of(run);
  return fmt::format("{}: {} on '{}'{}, {} fidelity; {}", run["name"].get<std::string>(),
                     show(run["workload"], Style::Text), show(run["hardware"], Style::Text),
                     sets == "none" ? "" : " with " + sets, show(run["level"], Style::Text),
                     run["rays"].get<std::string>());
}

std::string limit_of(const Json& run) {
  return run["bottleneck"].is_string() ? run["bottleneck"].get<std::string>()
                                       : "not known at the " + show(run["level"], Style::Text) +
                                             " fidelity level (cycle level only)";
}

}  // namespace

std::string compare_text(const Json& doc) {
  std::string out =
      fmt::format("compare    {} runs; ratios are to A, the first\n", doc["runs"].size());
  for (const Json& run : doc["runs"])
    out += fmt::format("{:<10} {}\n", run["label"].get<std::string>(), run_line(run));
  std::vector<Line> rows = lines(doc);
  std::vector<size_t> width(rows[0].cells.size() + 1, 0);
  for (const Line& l : rows) {
    width[0] = std::max(width[0], l.title.size());
    for (size_t c = 0; c < l.cells.size(); ++c)
      width[c + 1] = std::max(width[c + 1], l.cells[c].size());
  }
  for (const Line& l : rows) {
    out += fmt::format("{:<{}}", l.title, width[0]);
    for (size_t c = 0; c < l.cells.size(); ++c)
      out += fmt::format("  {:>{}}", l.cells[c], width[c + 1]);
    out += "\n";
  }
  for (const Json& run : doc["runs"])
    out += fmt::format("limit      {}: {}\n", run["label"].get<std::string>(), limit_of(run));
  for (const Json& note : doc["notes"]) out += "note       " + note.get<std::string>() + "\n";
  return out;
}

std::string compare_markdown(const Json& doc) {
  std::string out = "# rtsim compare\n\n" + doc["generator"].get<std::string>() +
                    " · data: compare.json · ratios are to A, the first run\n\n";
  for (const Json& run : doc["runs"])
    out += "- **" + run["label"].get<std::string>() + "** " + run_line(run) + " (`" +
           run["path"].get<std::string>() + "`)\n";
  std::vector<Line> rows = lines(doc);
  out += "\n| " + rows[0].title + " |";
  for (const std::string& c : rows[0].cells) out += " " + c + " |";
  out += "\n|---|";
  for (size_t c = 0; c < rows[0].cells.size(); ++c) out += "---:|";
  out += "\n";
  for (size_t r = 1; r < rows.size(); ++r) {
    out += "| " + rows[r].title + " |";
    for (const std::string& c : rows[r].cells) out += " " + c + " |";
    out += "\n";
  }
  out += "\n## What limits each run\n\n";
  for (const Json& run : doc["runs"])
    out += "- **" + run["label"].get<std::string>() + "**: " + limit_of(run) + "\n";
  if (!doc["notes"].empty()) out += "\n## Notes\n\n";
  for (const Json& note : doc["notes"]) out += "- " + note.get<std::string>() + "\n";
  return out;
}

std::string compare_html(const Json& doc) {
  const Json& runs = doc["runs"];
  std::string out = html_head("rtsim compare") + "<h1>rtsim compare</h1>\n<p class=\"meta\">" +
                    html_escape(doc["generator"].get<std::string>()) +
                    " &middot; data: compare.json &middot; ratios are to A, the first run; "
                    "green: better than A, red: worse</p>\n";
  out +=
      "<section id=\"runs\">\n<h2>Runs</h2>\n<table>\n<tr><th>run</th><th>folder</th>"
      "<th>workload</th><th>hardware</th><th>--set</th><th>fidelity</th><th>rays</th>"
      "<th>what limits it</th></tr>\n";
  for (size_t i = 0; i < runs.size(); ++i) {
    std::string p = "runs." + std::to_string(i);
    out += "<tr><th>" +
           html_escape(runs[i]["label"].get<std::string>() + ": " +
                       runs[i]["name"].get<std::string>()) +
           "</th>";
    for (const char* key : {".path", ".workload", ".hardware"})
      out += html_cell(doc, p + key, Style::Text);
    out += cell(p + ".sets", runs[i]["sets"], sets_of(runs[i]), "");
    for (const char* key : {".level", ".rays"}) out += html_cell(doc, p + key, Style::Text);
    out += "<td style=\"text-align:left\">" + html_escape(limit_of(runs[i])) + "</td></tr>\n";
  }
  out += "</table>\n</section>\n<section id=\"metrics\">\n<h2>Metrics</h2>\n<table>\n";
  std::vector<Line> rows = lines(doc);
  out += "<tr><th>metric</th>";
  for (const std::string& c : rows[0].cells) out += "<th>" + html_escape(c) + "</th>";
  out += "</tr>\n<tr><th>" + html_escape(rows[1].title) + "</th>";
  for (size_t i = 0; i < runs.size(); ++i)
    out += cell("runs." + std::to_string(i) + ".speedup", runs[i]["speedup"],
                times(runs[i]["speedup"]), verdict("speedup", runs[i]["speedup"])) +
           (i ? "<td></td>" : "");
  out += "</tr>\n";
  for (const Json& m : doc["metrics"]) {
    std::string name = m.get<std::string>();
    out += "<tr><th>" + html_escape(name) + "</th>";
    for (size_t i = 0; i < runs.size(); ++i) {
      // The metric's dotted name is one key of "metrics" and "ratios".
      std::string p = "runs." + std::to_string(i) + ".";
      const Json &v = runs[i]["metrics"][name], &r = runs[i]["ratios"][name];
      out += cell(p + "metrics." + name, v, show(v, metric_style(name)), "");
      if (i) out += cell(p + "ratios." + name, r, times(r), verdict(name, r));
    }
    out += "</tr>\n";
  }
  out += "</table>\n</section>\n";
  if (!doc["notes"].empty()) {
    out += "<section id=\"notes\">\n<h2>Notes</h2>\n<ul>\n";
    for (const Json& note : doc["notes"])
      out += "<li>" + html_escape(note.get<std::string>()) + "</li>\n";
    out += "</ul>\n</section>\n";
  }
  return out + html_tail();
}

}  // namespace rtsim::reports
