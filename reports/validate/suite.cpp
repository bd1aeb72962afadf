#include "reports/validate/suite.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

#include "reports/page_util.h"
#include "reports/validate/checks.h"

namespace rtsim::validation {

size_t SuiteResult::passed() const {
  size_t n = 0;
  for (const Check& c : checks) n += c.passed();
  return n;
}

size_t SuiteResult::skipped() const {
  size_t n = 0;
  for (const Check& c : checks) n += !c.ran();
  return n;
}

size_t SuiteResult::failed() const {
  size_t n = 0;
  for (const Check& c : checks) n += c.failed();
  return n;
}

size_t SuiteResult::reported() const {
  return checks.size() - passed() - failed() - skipped();
}

namespace {

// A group of checks that run together, and the prefixes of the ids they report (what --only
// selects them by).
struct Group {
  const char* name;
  std::vector<std::string> prefixes;
  bool quick;  // closed form: part of --quick
  std::function<std::vector<Check>()> run;
};

bool starts_with(const std::string& s, const std::string& prefix) {
  return s.compare(0, prefix.size(), prefix) == 0;
}

// Whether a selection (--only, empty: everything) may want a check whose id starts with
// `prefix`: one is the other's prefix.
bool may_select(const std::vector<std::string>& only, const std::string& prefix) {
  if (only.empty()) return true;
  for (const std::string& o : only)
    if (starts_with(prefix, o) || starts_with(o, prefix)) return true;
  return false;
}

bool selects(const std::vector<std::string>& only, const std::string& id) {
  if (only.empty()) return true;
  for (const std::string& o : only)
    if (starts_with(id, o)) return true;
  return false;
}

// The suite's groups, in the order they run.
std::vector<Group> suite_groups(const Target& target,
                                const std::function<void(const std::string&)>& progress) {
  return {
      {"latency ladder", {"ladder."}, true, [&] { return latency_ladder(target); }},
      {"throughput ceilings", {"ceiling."}, true, [&] { return throughput_ceilings(target); }},
      {"bandwidth rooflines",
       {"roofline."},
       true,
       [&] {
         std::vector<Check> checks = port_rooflines(target);
         for (Check& c : dram_roofline(target)) checks.push_back(std::move(c));
         return checks;
       }},
      {"DRAM latency under load",
       {"queueing."},
       true,
       [&] { return std::vector<Check>{dram_loaded_latency(target)}; }},
      {"Little's law", {"little."}, true, [&] { return std::vector<Check>{littles_law(target)}; }},
      {"published results",
       {"ylitie.", "aila_laine.", "vaidyanathan.", "aila_karras.", "boulos."},
       false,
       [&] { return published_checks(target, progress); }},
      {"vendor rates", {"vendor."}, false, [&] { return preset_checks(target, progress); }},
      {"sensitivity", {"sensitivity."}, false, [&] { return sensitivity_checks(target); }},
      {"sampling", {"sampling."}, false, [&] { return sampling_checks(target, progress); }}};
}

bool group_may_select(const Group& group, const std::vector<std::string>& only) {
  return std::any_of(group.prefixes.begin(), group.prefixes.end(),
                     [&](const std::string& p) { return may_select(only, p); });
}

}  // namespace

SuiteResult run_suite(const Target& target, bool quick,
                      const std::function<void(const std::string&)>& progress,
                      const std::vector<std::string>& only) {
  SuiteResult result;
  result.config_name = target.config.name;
  result.quick = quick;
  for (const Group& group : suite_groups(target, progress)) {
    if ((quick && !group.quick) || !group_may_select(group, only)) continue;
    progress(group.name);
    for (Check& c : group.run())
      if (selects(only, c.id)) result.checks.push_back(std::move(c));
  }
  return result;
}

std::string only_problem(const std::vector<std::string>& only) {
  std::vector<Group> groups = suite_groups(Target{}, {});
  std::string all;
  for (const Group& g : groups)
    for (const std::string& p : g.prefixes) all += (all.empty() ? "" : ", ") + p;
  for (const std::string& o : only) {
    if (o.empty()) return "--only: an empty prefix selects every check; leave --only out";
    if (std::none_of(groups.begin(), groups.end(),
                     [&](const Group& g) { return group_may_select(g, {o}); }))
      return fmt::format("--only {}: no check's id starts with it (ids start with {})", o, all);
  }
  return {};
}

nlohmann::ordered_json json_number(double value) {
  return std::isfinite(value) ? nlohmann::ordered_json(value) : nlohmann::ordered_json();
}

std::string show_value(double value) {
  return reports::show(json_number(value), reports::Style::Real);
}

nlohmann::ordered_json suite_json(const SuiteResult& r) {
  nlohmann::ordered_json checks = nlohmann::ordered_json::array();
  auto number = json_number;
  for (const Check& c : r.checks)
    checks.push_back({{"id", c.id},
                      {"suite", c.suite},
                      {"title", c.title},
                      {"status", c.status()},
                      {"unit", c.unit},
                      {"expected", number(c.expected)},
                      {"lo", number(c.lo)},
                      {"hi", number(c.hi)},
                      {"measured", number(c.measured)},
                      {"source", c.source},
                      {"detail", c.detail},
                      {"look_at", c.look_at},
                      {"skipped", c.skipped}});
  return {{"schema", kValidateSchema}, {"config", r.config_name},  {"config_path", r.config_path},
          {"quick", r.quick},          {"passed", r.passed()},     {"failed", r.failed()},
          {"skipped", r.skipped()},    {"reported", r.reported()}, {"checks", checks}};
}

}  // namespace rtsim::validation
