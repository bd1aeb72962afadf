#include "reports/compare.h"

#include <filesystem>

#include <fmt/core.h>

#include "reports/metrics.h"
#include "reports/page_util.h"
#include "reports/report_writer.h"
#include "reports/sim_folder.h"
#include "reports/sweep_report.h"
#include "traces/error.h"

namespace rtsim::reports {
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

namespace {

struct Run {
  std::string name, path;
  Json report;
};

// "workload key=value ..." of a sweep point.
std::string point_name(const Json& point) {
  std::string name = point["workload"].get<std::string>();
  for (const auto& [key, value] : point["values"].items())
    name += " " + key + "=" + (value.is_string() ? value.get<std::string>() : value.dump());
  return name;
}

// The finished points of a sweep folder; a point without a whole report.json is left out,
// with a note.
void add_sweep_points(const std::string& dir, std::vector<Run>& runs, Json& notes) {
  std::string path = dir + "/sweep.json";
  Json doc = read_json_file(path, kSweepSchema);
  using K = JsonKind;
  require_fields(doc, path,
                 {{"points", K::Array},
                  {"points.*.id", K::String},
                  {"points.*.workload", K::String},
                  {"points.*.values", K::Object}});
  for (const Json& point : doc["points"]) {
    std::string point_dir = dir + "/points/" + point["id"].get<std::string>();
    Json report = whole_report(point_dir + "/report.json");
    if (report.is_null())
      notes.push_back(point_dir + ": left out, no finished report.json");
    else
      runs.push_back({point_name(point), point_dir, report});
  }
}

std::string letter(size_t i) {
  return i < 26 ? std::string(1, char('A' + i)) : "R" + std::to_string(i + 1);
}

// A flat metric by its whole name (dots and all: "type.camera.nodes_per_ray" is one key).
Json metric_of(const Json& flat, const std::string& name) {
  auto it = flat.find(name);
  return it == flat.end() ? Json() : *it;
}

Json ratio(const Json& value, const Json& first) {
  if (!value.is_number() || !first.is_number() || first.get<double>() == 0) return Json();
  return value.get<double>() / first.get<double>();
}

// What the runs' workloads are, to say when the rays differ.
std::string rays_of(const Json& r) {
  const Json& w = r["workload"];
  return fmt::format("{} {}x{}, {} frame(s), {} rays", show(w["name"], Style::Text),
                     show(w["width"], Style::Integer), show(w["height"], Style::Integer),
                     show(w["frames"], Style::Integer), show(w["rays"], Style::Integer));
}

}  // namespace

const std::vector<std::string>& default_compare_metrics() {
  static const std::vector<std::string> names{"cycles",
                                              "mrays_per_second",
                                              "dram_bytes_per_ray",
                                              "l1_hit_rate",
                                              "l2_hit_rate",
                                              "nodes_per_ray",
                                              "triangles_per_ray",
                                              "on_chip_bytes",
                                              "energy_nj_per_ray",
                                              "area_mm2",
                                              "unexplained"};
  return names;
}

Json compare_runs(const std::vector<std::string>& args, const std::vector<std::string>& names) {
  std::vector<Run> runs;
  Json notes = Json::array();
  for (const std::string& arg : args) {
    if (fs::exists(arg + "/sweep.json"))
      add_sweep_points(arg, runs, notes);
    else
      runs.push_back(
          {fs::path(arg).lexically_normal().filename().string(), arg, read_run_report(arg)});
  }
  if (runs.size() < 2)
    throw InputError(
        fmt::format("compare: {} run(s) to compare; give at least two (run, sim or sweep folders)",
                    runs.size()));
  std::vector<Json> reports;
  for (const Run& r : runs) reports.push_back(r.report);
  std::vector<std::string> metrics = expand_metric_names(
      names.empty() ? default_compare_metrics() : names, reports, "compare: --metric");
  Json first = flat_metrics(runs[0].report);
  Json list = Json::array();
  for (size_t i = 0; i < runs.size(); ++i) {
    const Json& r = runs[i].report;
    Json flat = flat_metrics(r), values = Json::object(), ratios = Json::object();
    for (const std::string& m : metrics) {
      values[m] = metric_of(flat, m);
      ratios[m] = ratio(values[m], metric_of(first, m));
    }
    list.push_back({{"label", letter(i)},
                    {"name", runs[i].name},
                    {"path", runs[i].path},
                    {"workload", r["workload"]["name"]},
                    {"rays", rays_of(r)},
                    {"hardware", r["hardware"]["name"]},
                    {"sets", r["hardware"]["sets"]},
                    {"level", r["fidelity"]["level"]},
                    {"bottleneck", at_key(r, "timing.bottleneck.text")},
                    {"speedup", ratio(metric_of(first, "cycles"), metric_of(flat, "cycles"))},
                    {"metrics", values},
                    {"ratios", ratios}});
  }
  for (size_t i = 1; i < runs.size(); ++i)
    if (list[i]["level"] != list[0]["level"])
      notes.push_back(fmt::format(
          "{} ran at the {} fidelity level and A at the {} level: its ratios "
          "compare the models as well as the hardware",
          letter(i), list[i]["level"].get<std::string>(), list[0]["level"].get<std::string>()));
  for (size_t i = 1; i < runs.size(); ++i)
    if (list[i]["rays"] != list[0]["rays"])
      notes.push_back(fmt::format(
          "{} reads other rays than A ({}; A: {}): its ratios compare the "
          "workloads as well as the hardware",
          letter(i), list[i]["rays"].get<std::string>(), list[0]["rays"].get<std::string>()));
  Json doc;
  doc["schema"] = kCompareSchema;
  doc["generator"] = "rtsim " RTSIM_VERSION;
  doc["metrics"] = metrics;
  doc["runs"] = list;
  doc["notes"] = notes;
  return doc;
}

}  // namespace rtsim::reports
