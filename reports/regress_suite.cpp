#include "reports/regress_suite.h"

#include <algorithm>
#include <filesystem>
#include <optional>

#include <fmt/core.h>
#include <toml++/toml.h>

#include "model/config/config_reader.h"
#include "model/config/hw_config.h"
#include "model/fidelity/fidelity_result.h"
#include "reports/metrics.h"
#include "reports/spec_reader.h"
#include "traces/error.h"

namespace rtsim::reports {
namespace fs = std::filesystem;

namespace {

RegressCase read_case(const SpecReader& r, const toml::table& t, const toml::table* defaults,
                      const std::string& config) {
  std::vector<std::string> keys{"workload", "resolution", "frames",   "seed",       "scene",
                                "config",   "set",        "fidelity", "sample_rate"};
  if (defaults) r.only(*defaults, keys, "[defaults]");
  keys.push_back("name");
  r.only(t, keys, "[[case]]");
  auto pick = [&](const char* key) -> const toml::node* {
    if (const toml::node* n = t.get(key)) return n;
    return defaults ? defaults->get(key) : nullptr;
  };
  auto text = [&](const char* key, const std::string& def) { return r.text(pick(key), key, def); };
  RegressCase c;
  c.trace.workload = r.resolve(text("workload", "pica"));
  c.name = text("name", fs::path(c.trace.workload).stem().string());
  r.path_name(t.get("name") ? *t.get("name") : t, c.name, "[[case]] name");
  c.trace.resolution = text("resolution", "");
  c.trace.scene = text("scene", "");
  if (const toml::node* n = pick("frames"))
    c.trace.frames = uint32_t(r.integer(*n, "frames", 0, 1 << 20));
  if (const toml::node* n = pick("seed"))
    c.trace.seed = uint64_t(r.integer(*n, "seed", 0, INT64_MAX));
  c.config = r.resolve(text("config", config));
  if (const toml::node* n = pick("set")) c.sets = r.strings(*n, "set");
  c.fidelity = text("fidelity", "cycle");
  if (!fidelity_level_from_name(c.fidelity))
    r.fail(*pick("fidelity"), "'fidelity' must be functional, cache, cycle or sampled");
  if (const toml::node* n = pick("sample_rate"))
    c.sampling.rate = uint32_t(r.integer(*n, "sample_rate", 2, 1024));
  load_hw_config(c.config, c.sets);
  return c;
}

Tolerance read_tolerance(const SpecReader& r, const std::string& metric, const toml::node& n) {
  std::string problem = metric_name_problem(metric);
  if (!problem.empty()) r.fail(n, "[tolerance] " + problem);
  Tolerance t{metric, 0, 0, ""};
  if (!n.is_table()) {
    t.relative = r.non_negative(n, "tolerance '" + metric + "'");
    return t;
  }
  const toml::table& table = *n.as_table();
  r.only(table, {"relative", "absolute", "direction"}, "tolerance '" + metric + "'");
  if (const toml::node* v = table.get("relative")) t.relative = r.non_negative(*v, "relative");
  if (const toml::node* v = table.get("absolute")) t.absolute = r.non_negative(*v, "absolute");
  t.direction = r.text(table, "direction", "");
  if (!t.direction.empty() && t.direction != "lower" && t.direction != "higher" &&
      t.direction != "either")
    r.fail(n, "direction must be lower, higher or either");
  return t;
}

}  // namespace

RegressSuite read_regress_suite(const std::string& path) {
  SpecReader r{path};
  toml::table root = parse_config_file(path, "regression suite");
  r.only(root, {"name", "description", "config", "verify", "defaults", "case", "tolerance"},
         "the suite");
  RegressSuite suite;
  suite.file = path;
  suite.name = r.text(root, "name", fs::path(path).stem().string());
  suite.description = r.text(root, "description", "");
  if (const toml::node* v = root.get("verify")) suite.verify = r.boolean(*v, "verify");
  std::string config = r.text(root, "config", "");
  const toml::array* cases = root["case"].as_array();
  if (!cases || cases->empty()) throw_input_error(path, "", "no [[case]]");
  for (const toml::node& n : *cases) {
    if (!n.is_table()) r.fail(n, "[[case]] must be a table");
    suite.cases.push_back(read_case(r, *n.as_table(), root["defaults"].as_table(), config));
    for (size_t i = 0; i + 1 < suite.cases.size(); ++i)
      if (suite.cases[i].name == suite.cases.back().name)
        r.fail(n, "two cases named '" + suite.cases.back().name + "'");
  }
  const toml::table* tolerances = root["tolerance"].as_table();
  if (!tolerances || tolerances->empty())
    throw_input_error(path, "", "no [tolerance] table: which metrics does the suite compare?");
  for (const auto& [metric, node] : *tolerances)
    suite.tolerances.push_back(read_tolerance(r, std::string(metric.str()), node));
  return suite;
}

}  // namespace rtsim::reports
