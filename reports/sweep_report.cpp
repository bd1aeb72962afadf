#include "reports/sweep_report.h"

#include <algorithm>
#include <filesystem>
#include <utility>

#include <fmt/core.h>

#include "model/sc/sim_report.h"
#include "reports/charts.h"
#include "reports/page_util.h"
#include "traces/error.h"
#include "traces/path_name.h"

namespace rtsim::reports {
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

namespace {

std::string chart_file(const std::string& id) {
  return "images/" + id + ".png";
}

bool numeric_key(const Json& points, const std::string& key) {
  for (const Json& p : points)
    if (!p["values"].contains(key) || !p["values"][key].is_number()) return false;
  return true;
}

std::string chart_title(const Json& c) {
  std::string y = c["y"].get<std::string>();
  if (y.rfind("type.*.", 0) == 0) y = y.substr(7) + " per ray type";
  return fmt::format("{} against {}", y, c["x"].get<std::string>());
}

// The curves asked for, or cycles and DRAM bytes per ray (per ray type) against each numeric
// key; then the Pareto charts of cycles against each cost: on-chip bytes, area, energy.
Json chart_list(const SweepSpec& spec, const Json& points) {
  Json charts = Json::array();
  auto add = [&](const std::string& x, const std::string& y, const std::string& series) {
    charts.push_back({{"id", "curve_" + std::to_string(charts.size())},
                      {"kind", "curve"},
                      {"x", x},
                      {"y", y},
                      {"series", series}});
  };
  for (const SweepChart& c : spec.charts) add(c.x, c.y, c.series);
  if (spec.charts.empty())
    for (const std::string& key : spec.keys)
      if (numeric_key(points, key)) {
        add(key, "cycles", "workload");
        add(key, "type.*.dram_bytes_per_ray", "workload");
      }
  for (Json& c : charts) c["title"] = chart_title(c);
  struct Cost {
    const char *id, *metric, *what;
  };
  for (const Cost& c :
       {Cost{"pareto", "on_chip_bytes", "on-chip memory"}, Cost{"pareto_area", "area_mm2", "area"},
        Cost{"pareto_energy", "energy_nj_per_ray", "energy per ray"}})
    charts.push_back({{"id", c.id},
                      {"kind", "pareto"},
                      {"x", c.metric},
                      {"y", "cycles"},
                      {"series", "workload"},
                      {"title", std::string("Pareto: cycles against ") + c.what}});
  for (Json& c : charts) {
    c["file"] = chart_file(c["id"].get<std::string>());
    c["available"] = true;
    c["reason"] = "";
  }
  return charts;
}

// A point's metric, null when it has none (a failed point, a level that does not model it).
const Json& metric_of(const Json& point, const std::string& name) {
  static const Json null;
  const Json& m = point["metrics"];
  auto it = m.is_object() ? m.find(name) : m.end();
  return it != m.end() && it->is_number() ? *it : null;
}

// Charts whose x metric no point has (energy and area below cycle level) are left out.
void mark_unmeasured_charts(Json& doc) {
  for (Json& c : doc["charts"]) {
    std::string x = c["x"].get<std::string>();
    if (c["kind"] != "pareto" || !c["available"].get<bool>()) continue;
    bool any = false;
    for (const Json& p : doc["points"]) any |= !metric_of(p, x).is_null();
    if (!any) {
      c["available"] = false;
      c["reason"] = "no point has " + x + " (the energy and area model needs the cycle level)";
    }
  }
}

// Per workload, the point the objective picks: among points whose metric is known and within
// every bound, the least (or most) of the metric; a tie goes to the earlier point.
Json objective_json(const SweepSpec& spec, const Json& points) {
  const SweepObjective& o = spec.objective;
  if (o.metric.empty()) return Json();
  auto bounds = [](const std::vector<std::pair<std::string, double>>& list) {
    Json out = Json::object();
    for (const auto& [metric, bound] : list) out[metric] = bound;
    return out;
  };
  auto within = [&](const Json& p) {  // sign: +1 bounds from above, -1 from below
    for (const auto& [list, sign] : {std::pair{&o.at_most, 1.0}, std::pair{&o.at_least, -1.0}})
      for (const auto& [metric, bound] : *list) {
        const Json& v = metric_of(p, metric);
        if (v.is_null() || sign * (v.get<double>() - bound) > 0) return false;
      }
    return true;
  };
  double direction = o.maximise ? -1 : 1;  // the pick has the least direction x metric
  Json best = Json::array();
  for (const SweepWorkload& w : spec.workloads) {
    const Json* pick = nullptr;
    double least = 0;
    size_t measured = 0;
    for (const Json& p : points) {
      if (p["workload"] != w.name || metric_of(p, o.metric).is_null()) continue;
      ++measured;
      double value = direction * metric_of(p, o.metric).get<double>();
      if (within(p) && (!pick || value < least)) pick = &p, least = value;
    }
    Json entry = {{"workload", w.name}};
    if (pick) {
      entry["id"] = (*pick)["id"];
      entry["values"] = (*pick)["values"];
      entry["value"] = metric_of(*pick, o.metric);
      Json constrained = Json::object();
      for (const auto& list : {o.at_most, o.at_least})
        for (const auto& bound : list) constrained[bound.first] = metric_of(*pick, bound.first);
      entry["bounded_metrics"] = constrained;
    } else {
      entry["id"] = Json();
      entry["reason"] = measured ? "no point is within the bounds" : "no point has " + o.metric;
    }
    best.push_back(entry);
  }
  return {{"metric", o.metric},
          {"goal", o.maximise ? "maximise" : "minimise"},
          {"at_most", bounds(o.at_most)},
          {"at_least", bounds(o.at_least)},
          {"best", best}};
}

std::string csv_field(const Json& v) {
  if (v.is_null()) return "";
  if (v.is_string()) return v.get<std::string>();
  return v.dump();
}

// A point that never ran (a Slurm sweep collected early) is missing, not failed.
const char* point_status(const PointRun& p) {
  if (p.ok) return p.reused ? "reused" : "done";
  return p.ran_on.empty() && p.exit_code == 0 ? "missing" : "failed";
}

// What the pages, the CSV and the objective's lines read from a sweep.json written before.
void require_sweep_fields(const Json& doc, const std::string& path) {
  using K = JsonKind;
  require_fields(doc, path,
                 {
                     {"generator", K::String},       {"spec.name", K::String},
                     {"spec.file", K::String},       {"spec.description", K::String},
                     {"spec.config", K::String},     {"spec.fidelity", K::String},
                     {"spec.workloads", K::Present}, {"spec.keys", K::Array},
                     {"spec.keys.*", K::String},     {"points", K::Array},
                     {"points.*.id", K::String},     {"points.*.workload", K::String},
                     {"points.*.status", K::String}, {"points.*.ran_on", K::String},
                     {"points.*.values", K::Object}, {"points.*.metrics", K::ObjectOrNull},
                     {"charts", K::Array},           {"charts.*.id", K::String},
                     {"charts.*.kind", K::String},   {"charts.*.x", K::String},
                     {"charts.*.y", K::String},      {"charts.*.series", K::String},
                     {"charts.*.title", K::String},  {"charts.*.reason", K::String},
                     {"objective", K::ObjectOrNull},
                 });
  for (size_t i = 0; i < doc["charts"].size(); ++i) {
    std::string problem = path_name_problem(doc["charts"][i]["id"].get<std::string>());
    if (!problem.empty())
      throw_input_error(path, fmt::format("key charts.{}.id", i), problem + " (names its image)");
  }
  const Json& o = doc["objective"];
  if (o.is_null()) return;
  require_fields(doc, path,
                 {{"objective.metric", K::String},
                  {"objective.goal", K::String},
                  {"objective.at_most", K::Object},
                  {"objective.at_least", K::Object},
                  {"objective.at_most.*", K::Number},
                  {"objective.at_least.*", K::Number},
                  {"objective.best", K::Array},
                  {"objective.best.*.workload", K::String},
                  {"objective.best.*.id", K::Present}});
  for (size_t i = 0; i < o["best"].size(); ++i) {
    std::string b = fmt::format("objective.best.{}.", i);
    if (o["best"][i]["id"].is_null()) {
      require_fields(doc, path, {{b + "reason", K::String}});
      continue;
    }
    require_fields(doc, path,
                   {{b + "id", K::String}, {b + "values", K::Object}, {b + "value", K::Number}});
    for (const char* side : {"at_most", "at_least"})
      for (const auto& [name, bound] : o[side].items())
        require_fields(doc, path, {{b + "bounded_metrics." + name, K::Number}});
  }
}

}  // namespace

Json sweep_json(const SweepSpec& spec, const std::vector<PointRun>& runs) {
  Json points = Json::array();
  for (const PointRun& p : runs)
    points.push_back({{"id", p.id},
                      {"workload", p.workload},
                      {"values", p.point->values},
                      {"status", point_status(p)},
                      {"exit_code", p.exit_code},
                      {"ran_on", p.ran_on},
                      {"dir", "points/" + p.id},
                      {"metrics", p.ok ? p.metrics : Json()}});
  Json workloads = Json::array();
  for (const SweepWorkload& w : spec.workloads)
    workloads.push_back({{"name", w.name},
                         {"workload", w.trace.workload},
                         {"resolution", w.trace.resolution},
                         {"frames", w.trace.frames}});
  Json doc;
  doc["schema"] = kSweepSchema;
  doc["generator"] = "rtsim " RTSIM_VERSION;
  doc["spec"] = {
      {"file", spec.file},     {"name", spec.name},         {"description", spec.description},
      {"config", spec.config}, {"sets", spec.sets},         {"workloads", workloads},
      {"keys", spec.keys},     {"fidelity", spec.fidelity}, {"sample_rate", spec.sampling.rate},
      {"verify", spec.verify}};
  doc["points"] = points;
  doc["charts"] = chart_list(spec, points);
  doc["objective"] = objective_json(spec, points);
  return doc;
}

std::string sweep_csv(const Json& doc) {
  std::vector<std::string> metrics;
  for (const Json& p : doc["points"])
    if (p["metrics"].is_object())
      for (const auto& [name, value] : p["metrics"].items())
        if (std::find(metrics.begin(), metrics.end(), name) == metrics.end())
          metrics.push_back(name);
  std::string out = "workload,id,status,ran_on";
  for (const Json& k : doc["spec"]["keys"]) out += "," + k.get<std::string>();
  for (const std::string& m : metrics) out += "," + m;
  out += "\n";
  for (const Json& p : doc["points"]) {
    out += p["workload"].get<std::string>() + "," + p["id"].get<std::string>() + "," +
           p["status"].get<std::string>() + "," + p.value("ran_on", "");
    for (const Json& k : doc["spec"]["keys"])
      out += "," + csv_field(swept_value(p["values"], k.get<std::string>()));
    for (const std::string& m : metrics)
      out +=
          "," + (p["metrics"].is_object() && p["metrics"].contains(m) ? csv_field(p["metrics"][m])
                                                                      : std::string());
    out += "\n";
  }
  return out;
}

std::vector<std::string> objective_lines(const Json& doc) {
  std::vector<std::string> lines;
  const Json& o = doc.contains("objective") ? doc["objective"] : Json();
  if (o.is_null()) return lines;
  std::string metric = o["metric"].get<std::string>();
  for (const Json& b : o["best"]) {
    std::string line = b["workload"].get<std::string>() + ": ";
    if (b["id"].is_null()) {
      lines.push_back(line + "none (" + b["reason"].get<std::string>() + ")");
      continue;
    }
    std::string values, bounds;
    for (const auto& [key, value] : b["values"].items())
      values += (values.empty() ? " at " : ", ") + key + "=" + csv_field(value);
    for (const auto& [side, relation] : {std::pair{"at_most", "<="}, std::pair{"at_least", ">="}})
      for (const auto& [name, bound] : o[side].items())
        bounds +=
            fmt::format("; {} = {:.4g} {} {:.4g}", name, b["bounded_metrics"][name].get<double>(),
                        relation, bound.get<double>());
    lines.push_back(fmt::format("{}{} {:.4g} ({}){} (point {}{})", line, metric,
                                b["value"].get<double>(), o["goal"].get<std::string>(), values,
                                b["id"].get<std::string>(), bounds));
  }
  return lines;
}

ReportOutcome write_sweep_report(Json& doc, const std::string& dir, const ReportOptions& options) {
  fs::create_directories(dir + "/images");
  std::string json_path = dir + "/sweep.json";
  mark_unmeasured_charts(doc);
  write_file_atomic(json_path, doc.dump(2) + "\n");
  write_file_atomic(dir + "/sweep.csv", sweep_csv(doc));
  ReportOutcome outcome{false, "charts skipped (--no-charts)"};
  if (options.charts) {
    ChartRun charts = run_chart_script("sweep_charts.py", {json_path, dir});
    outcome = {charts.ok, charts.message};
  }
  for (Json& c : doc["charts"])
    if (!fs::exists(dir + "/" + c["file"].get<std::string>())) {
      c["available"] = false;
      c["reason"] = outcome.charts_ok ? "file missing" : outcome.message;
    }
  write_file_atomic(json_path, doc.dump(2) + "\n");
  write_file_atomic(dir + "/sweep.html", sweep_html(doc, dir));
  write_file_atomic(dir + "/sweep.md", sweep_markdown(doc));
  return outcome;
}

ReportOutcome rewrite_sweep_report(const std::string& dir, const ReportOptions& options) {
  std::string path = dir + "/sweep.json";
  Json doc = read_json_file(path, kSweepSchema);
  require_sweep_fields(doc, path);
  for (Json& c : doc["charts"]) {
    c["available"] = true;
    c["file"] = chart_file(c["id"].get<std::string>());  // never a path from the file
  }
  return write_sweep_report(doc, dir, options);
}

}  // namespace rtsim::reports
