// `rtsim validate`: runs the checks on one hardware config and writes what they found
// (terminal table, validate.md, validate.html, validate.json, junit.xml). model/VALIDATION.md
// explains each check and how to add one.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/config/hw_config.h"
#include "reports/validate/check.h"
#include "reports/validate/sim_runs.h"

namespace rtsim::validation {

constexpr const char* kValidateSchema = "rtsim.validate/1";

struct SuiteResult {
  std::string config_name, config_path;
  bool quick = false;
  std::vector<Check> checks;
  size_t passed() const;
  size_t failed() const;
  size_t skipped() const;
  size_t reported() const;  // info: figures without a band
};

// Runs the suite (quick: the closed-form checks only; only: the checks whose id starts with one
// of these prefixes, every check when empty, and only the groups that report such ids run);
// `progress` hears each group's name as it starts.
SuiteResult run_suite(const Target& target, bool quick,
                      const std::function<void(const std::string&)>& progress,
                      const std::vector<std::string>& only = {});
// What is wrong with an --only list (a prefix no check's id starts with), or "".
std::string only_problem(const std::vector<std::string>& only);

nlohmann::ordered_json suite_json(const SuiteResult& result);
std::string terminal_table(const SuiteResult& result);
std::string markdown_page(const SuiteResult& result);
std::string html_page(const SuiteResult& result);
std::string junit_xml(const SuiteResult& result);

// A value as the JSON holds it: null where it is not finite (JSON has no NaN or infinity: a
// value not measured, an open band's missing side).
nlohmann::ordered_json json_number(double value);
// How a check's value is shown on every page: as reports::show shows a real ("n/a" for null).
std::string show_value(double value);

}  // namespace rtsim::validation
