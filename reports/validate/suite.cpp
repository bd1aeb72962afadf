#include "reports/validate/suite.h"

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

SuiteResult run_suite(const Target& target, bool quick,
                      const std::function<void(const std::string&)>& progress) {
  SuiteResult result;
  result.config_name = target.config.name;
  result.quick = quick;
  auto add = [&result](std::vector<Check> checks) {
    for (Check& c : checks) result.checks.push_back(std::move(c));
  };
  progress("latency ladder");
  add(latency_ladder(target));
  progress("throughput ceilings");
  add(throughput_ceilings(target));
  progress("bandwidth rooflines");
  add(port_rooflines(target));
  add(dram_roofline(target));
  progress("DRAM latency under load");
  add({dram_loaded_latency(target)});
  progress("Little's law");
  add({littles_law(target)});
  if (quick) return result;
  add(published_checks(target, progress));
  add(preset_checks(target, progress));
  progress("sensitivity");
  add(sensitivity_checks(target));
  add(sampling_checks(target, progress));
  return result;
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
