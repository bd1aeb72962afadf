#include "reports/sweep_spec.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <set>

#include <fmt/core.h>
#include <toml++/toml.h>

#include "model/config/config_reader.h"
#include "model/config/hw_config.h"
#include "model/fidelity/fidelity_result.h"
#include "reports/metrics.h"
#include "reports/spec_reader.h"
#include "traces/byte_size.h"
#include "traces/error.h"
#include "workloads/pipeline/spec.h"
#include "workloads/scene.h"

namespace rtsim::reports {
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

namespace {

// A TOML value of key as the text of --set KEY=VALUE, and as JSON. A size ("4M" for a key in
// bytes, traces/byte_size.h) is its bytes, so that points, tables and chart axes order it.
std::pair<std::string, Json> scalar(const SpecReader& r, const std::string& key,
                                    const toml::node& n) {
  if (auto v = n.value_exact<int64_t>()) return {std::to_string(*v), *v};
  if (auto v = n.value_exact<double>()) return {fmt::format("{}", *v), *v};
  if (auto v = n.value_exact<bool>()) return {*v ? "true" : "false", *v};
  if (auto v = n.value_exact<std::string>()) {
    bool in_bytes = key.size() > 6 && key.compare(key.size() - 6, 6, "_bytes") == 0;
    uint64_t bytes = 0;
    if (in_bytes && byte_size_problem(*v, &bytes).empty()) return {std::to_string(bytes), bytes};
    return {"\"" + *v + "\"", *v};
  }
  r.fail(n, "a config value must be an integer, number, boolean or string");
}

void flatten_into(const toml::table& t, const std::string& prefix,
                  std::vector<std::pair<std::string, const toml::node*>>& out) {
  for (const auto& [key, node] : t) {
    std::string name = prefix + std::string(key.str());
    if (node.is_table())
      flatten_into(*node.as_table(), name + ".", out);
    else
      out.emplace_back(name, &node);
  }
}

// Flattens nested tables into dotted keys ("rt.l1.size_bytes"); a key given twice (`"rt.count"`
// and `rt.count`, or `[grid.rt] count`) is refused, naming both lines.
std::vector<std::pair<std::string, const toml::node*>> flatten(const SpecReader& r,
                                                               const toml::table& t) {
  std::vector<std::pair<std::string, const toml::node*>> out;
  flatten_into(t, "", out);
  if (out.size() > kMostSweptKeys)
    r.fail(t, fmt::format("{} keys, more than {} (a config has under 200)", out.size(),
                          kMostSweptKeys));
  std::map<std::string, const toml::node*> seen;
  for (const auto& [name, node] : out) {
    auto [first, fresh] = seen.emplace(name, node);
    if (fresh) continue;
    uint32_t a = first->second->source().begin.line, b = node->source().begin.line;
    r.fail(a > b ? *first->second : *node, fmt::format("'{}' is given twice, on lines {} and {}",
                                                       name, std::min(a, b), std::max(a, b)));
  }
  return out;
}

// a x b, or UINT64_MAX where that overflows: counts from a spec are multiplied checked.
uint64_t times(uint64_t a, uint64_t b) {
  uint64_t product = 0;
  return __builtin_mul_overflow(a, b, &product) ? UINT64_MAX : product;
}

// Refuses a sweep of more points (workloads x configs) than max_points, from the count alone.
void check_point_count(const SpecReader& r, const toml::node& n, const std::string& what,
                       uint64_t count, std::string product, size_t workloads, uint64_t max_points) {
  if (count <= max_points) return;
  if (workloads > 1) product += fmt::format(" x {} workloads", workloads);
  std::string how = count <= kMostSweepPoints
                        ? fmt::format(", or pass --max-points {} to run them all", count)
                        : fmt::format(" (--max-points takes at most {})", kMostSweepPoints);
  r.fail(n, fmt::format("{} has {}{} points ({}), more than the limit of {}: narrow it{}", what,
                        count == UINT64_MAX ? "at least " : "", count, product, max_points, how));
}

void add_grid(const SpecReader& r, const toml::table& grid, uint64_t max_points, SweepSpec& spec) {
  std::vector<std::pair<std::string, const toml::node*>> axes = flatten(r, grid);
  uint64_t count = spec.workloads.size();
  std::string product;
  for (const auto& [key, node] : axes) {
    const toml::array* values = node->as_array();
    if (!values || values->empty()) r.fail(*node, "grid key '" + key + "' needs a list of values");
    count = times(count, values->size());
    product += (product.empty() ? "" : " x ") + std::to_string(values->size());
  }
  check_point_count(r, grid, "the grid", count, product, spec.workloads.size(), max_points);
  spec.points.push_back({Json::object(), {}, {}});
  for (const auto& [key, node] : axes) {
    const toml::array* values = node->as_array();
    spec.keys.push_back(key);
    std::set<std::string> listed;
    for (const toml::node& v : *values)
      if (!listed.insert(scalar(r, key, v).first).second)
        r.fail(v, fmt::format("grid key '{}' lists {} twice (its points would run twice)", key,
                              scalar(r, key, v).first));
    std::vector<SweepPoint> next;
    for (const SweepPoint& p : spec.points)
      for (const toml::node& v : *values) {
        SweepPoint q = p;
        auto [set, json] = scalar(r, key, v);
        q.values[key] = json;
        q.sets.push_back(key + "=" + set);
        q.lines.push_back(v.source().begin.line);
        next.push_back(q);
      }
    spec.points = next;
  }
}

// The [[point]] list; a point that sets the same values as an earlier one is refused, naming
// both lines.
void add_points(const SpecReader& r, const toml::array& list, uint64_t max_points,
                SweepSpec& spec) {
  check_point_count(r, list, "the [[point]] list", times(list.size(), spec.workloads.size()),
                    std::to_string(list.size()) + " [[point]]", spec.workloads.size(), max_points);
  std::map<std::vector<std::string>, uint32_t> seen;  // sorted settings -> line
  std::set<std::string> swept;
  for (const toml::node& n : list) {
    if (!n.is_table()) r.fail(n, "[[point]] must be a table");
    SweepPoint p{Json::object(), {}, {}};
    for (const auto& [key, node] : flatten(r, *n.as_table())) {
      auto [set, json] = scalar(r, key, *node);
      p.values[key] = json;
      p.sets.push_back(key + "=" + set);
      p.lines.push_back(node->source().begin.line);
      if (swept.insert(key).second) spec.keys.push_back(key);
    }
    if (swept.size() > kMostSweptKeys)
      r.fail(n, fmt::format("the points set {} keys, more than {} (a config has under 200)",
                            swept.size(), kMostSweptKeys));
    std::vector<std::string> settings = p.sets;
    std::sort(settings.begin(), settings.end());
    auto [earlier, fresh] = seen.emplace(settings, n.source().begin.line);
    if (!fresh)
      r.fail(n, fmt::format("this [[point]] sets the same values as the one on line {} (it would "
                            "run twice)",
                            earlier->second));
    spec.points.push_back(p);
  }
}

void read_workloads(const SpecReader& r, const toml::table& root, SweepSpec& spec) {
  const toml::array* list = root["workload"].as_array();
  if (!list || list->empty()) throw_input_error(r.file, "", "no [[workload]]");
  for (const toml::node& n : *list) {
    const toml::table* t = n.as_table();
    if (!t) r.fail(n, "[[workload]] must be a table");
    r.only(*t, {"name", "workload", "resolution", "frames", "seed", "scene"}, "[[workload]]");
    SweepWorkload w;
    w.trace.workload = r.resolve(r.text(*t, "workload", "pica"));
    w.name = r.text(*t, "name", fs::path(w.trace.workload).stem().string());
    r.path_name(t->get("name") ? *t->get("name") : n, w.name, "[[workload]] name");
    if (!is_builtin_scene(w.trace.workload) && !fs::exists(w.trace.workload))
      r.fail(*t->get("workload"), "workload '" + w.trace.workload +
                                      "': no such workload spec (.toml), scene file or built-in "
                                      "scene");
    w.trace.resolution = r.text(*t, "resolution");
    uint32_t width = 0, height = 0;
    if (!w.trace.resolution.empty() &&
        !pipeline::parse_resolution(w.trace.resolution, width, height))
      r.fail(*t->get("resolution"),
             "resolution '" + w.trace.resolution + "': expected WxH, e.g. \"1920x1080\"");
    w.trace.frames = uint32_t(r.integer(*t, "frames", 0, 0, 1 << 20));
    if (t->get("seed")) w.trace.seed = uint64_t(r.integer(*t, "seed", 1, 0, INT64_MAX));
    w.trace.scene = r.resolve(r.text(*t, "scene"));
    for (const SweepWorkload& other : spec.workloads)
      if (other.name == w.name)
        r.fail(n, "two workloads are named '" + w.name + "' (their traces would share a folder)");
    spec.workloads.push_back(w);
  }
}

void read_run(const SpecReader& r, const toml::table& run, SweepSpec& spec) {
  r.only(run, {"fidelity", "sample_rate", "verify", "jobs"}, "[run]");
  spec.fidelity = r.text(run, "fidelity", "cycle");
  if (!fidelity_level_from_name(spec.fidelity))
    r.fail(*run.get("fidelity"), "'fidelity' must be functional, cache, cycle or sampled");
  spec.sampling.rate = uint32_t(r.integer(run, "sample_rate", 16, 2, 1024));
  spec.jobs = uint32_t(r.integer(run, "jobs", 0, 0, 1024));
  if (const toml::node* v = run.get("verify")) spec.verify = r.boolean(*v, "verify");
}

void read_charts(const SpecReader& r, const toml::table& root, SweepSpec& spec) {
  const toml::array* list = root["chart"].as_array();
  if (!list) return;
  for (const toml::node& n : *list) {
    const toml::table* t = n.as_table();
    if (!t) r.fail(n, "[[chart]] must be a table");
    r.only(*t, {"x", "y", "series"}, "[[chart]]");
    SweepChart c{r.text(*t, "x"), r.text(*t, "y", "cycles"), r.text(*t, "series", "workload")};
    if (std::find(spec.keys.begin(), spec.keys.end(), c.x) == spec.keys.end())
      r.fail(t->get("x") ? *t->get("x") : n, "chart x '" + c.x + "' is not a swept key");
    std::string problem = metric_name_problem(c.y);
    if (!problem.empty()) r.fail(t->get("y") ? *t->get("y") : n, "chart y: " + problem);
    if (c.series != "workload" &&
        std::find(spec.keys.begin(), spec.keys.end(), c.series) == spec.keys.end())
      r.fail(*t->get("series"),
             "chart series '" + c.series + "' is neither 'workload' nor a swept key");
    spec.charts.push_back(c);
  }
}

// A metric a point is judged by: one of flat_metrics, of one ray type if per type.
void check_objective_metric(const SpecReader& r, const toml::node& n, const std::string& name) {
  std::string problem = metric_name_problem(name);
  if (problem.empty() && name.find('*') != std::string::npos)
    problem = "'" + name + "' names every ray type: pick one";
  if (!problem.empty()) r.fail(n, problem);
}

void read_objective(const SpecReader& r, const toml::table& t, SweepObjective& o) {
  r.only(t, {"minimise", "maximise", "at_most", "at_least"}, "[objective]");
  const toml::node *min = t.get("minimise"), *max = t.get("maximise");
  if (bool(min) == bool(max)) r.fail(t, "[objective] needs one of minimise or maximise");
  o.maximise = max != nullptr;
  o.metric = r.text(max ? max : min, max ? "maximise" : "minimise");
  check_objective_metric(r, max ? *max : *min, o.metric);
  for (const auto& [key, bounds] :
       {std::pair{"at_most", &o.at_most}, std::pair{"at_least", &o.at_least}}) {
    const toml::node* n = t.get(key);
    if (!n) continue;
    const toml::table* table = n->as_table();
    if (!table) r.fail(*n, std::string(key) + " must be a table of metric = bound");
    for (const auto& [name, bound] : *table) {
      std::string metric = std::string(name.str());
      check_objective_metric(r, bound, metric);
      std::optional<double> value = bound.value<double>();
      if (!value) r.fail(bound, std::string(key) + "." + metric + " must be a number");
      bounds->emplace_back(metric, *value);
    }
  }
}

// Loads a point's config; if that fails, blames the spec's line of the first setting (the
// spec's `set`, then the point's) that makes it fail, not --set or the preset file.
void check_point_config(const SweepSpec& spec, const SweepPoint& p, uint32_t set_line) {
  std::vector<std::string> sets = spec.sets;
  std::vector<uint32_t> lines(spec.sets.size(), set_line);
  sets.insert(sets.end(), p.sets.begin(), p.sets.end());
  lines.insert(lines.end(), p.lines.begin(), p.lines.end());
  try {
    load_hw_config(spec.config, sets);
    return;
  } catch (const InputError& whole) {
    for (size_t n = 0; n < sets.size(); ++n) {
      try {
        load_hw_config(spec.config, {sets.begin(), sets.begin() + long(n) + 1});
      } catch (const InputError& e) {
        throw_input_error(spec.file, fmt::format("line {}", lines[n]),
                          sets[n] + ": " + e.problem());
      }
    }
    throw;  // the config fails without any of the spec's settings: the preset file's own line
  }
}

}  // namespace

SweepSpec read_sweep_spec(const std::string& path, uint64_t max_points) {
  SpecReader r{path};
  toml::table root = parse_config_file(path, "sweep spec");
  r.only(root,
         {"name", "description", "config", "set", "workload", "grid", "point", "run", "chart",
          "objective"},
         "the sweep spec");
  SweepSpec spec;
  spec.file = path;
  spec.max_points = max_points;
  spec.name = r.text(root, "name", fs::path(path).stem().string());
  spec.description = r.text(root, "description");
  spec.config = r.resolve(r.text(root, "config"));
  if (const toml::node* sets = root.get("set")) spec.sets = r.strings(*sets, "set");
  read_workloads(r, root, spec);
  bool grid = root["grid"].is_table(), list = root["point"].is_array();
  if (grid && list) throw_input_error(path, "", "give either [grid] or [[point]] lists, not both");
  if (!grid && !list) throw_input_error(path, "", "no [grid] table or [[point]] list to sweep");
  if (grid) add_grid(r, *root["grid"].as_table(), max_points, spec);
  if (list) add_points(r, *root["point"].as_array(), max_points, spec);
  if (const toml::table* run = root["run"].as_table()) read_run(r, *run, spec);
  read_charts(r, root, spec);
  if (const toml::node* objective = root.get("objective")) {
    if (!objective->is_table()) r.fail(*objective, "[objective] must be a table");
    read_objective(r, *objective->as_table(), spec.objective);
  }
  uint32_t set_line = root.get("set") ? root.get("set")->source().begin.line : 0;
  for (const SweepPoint& p : spec.points) check_point_config(spec, p, set_line);
  return spec;
}

}  // namespace rtsim::reports
