// rtsim validate: the timing model checked against closed-form answers (model/VALIDATION.md).
// Exit 1 when a check fails, 2 on bad input.
#include <memory>

#include <fmt/core.h>

#include "app/commands.h"
#include "model/sc/sim_report.h"
#include "reports/validate/suite.h"
#include "traces/error.h"
#include "traces/host_clock.h"
#include "traces/output_file.h"

namespace rtsim::app {
namespace {

struct ValidateOptions {
  std::string config, output;
  std::vector<std::string> sets, only;
  bool quick = false;
};

int run_validate(const ValidateOptions& o) {
  std::string problem = validation::only_problem(o.only);
  if (!problem.empty()) throw InputError(problem);
  HwConfig config = load_hw_config(o.config, o.sets);
  if (!o.output.empty()) {
    create_output_folder(o.output);
    lock_output_folder(o.output, "rtsim validate");
  }
  double start = wall_seconds();
  validation::SuiteResult result = validation::run_suite(
      {config, {}}, o.quick,
      [&start](const std::string& group) {
        fmt::print(stderr, "[{:6.1f} s] {}\n", wall_seconds() - start, group);
      },
      o.only);
  result.config_path = o.config;
  fmt::print("{}", validation::terminal_table(result));
  if (!o.output.empty()) {
    write_file_atomic(o.output + "/validate.json", validation::suite_json(result).dump(2) + "\n");
    write_file_atomic(o.output + "/validate.md", validation::markdown_page(result));
    write_file_atomic(o.output + "/validate.html", validation::html_page(result));
    write_file_atomic(o.output + "/junit.xml", validation::junit_xml(result));
    fmt::print("wrote {0}/validate.html, validate.md, validate.json, junit.xml ({1:.1f} s)\n",
               o.output, wall_seconds() - start);
  }
  return result.failed() > 0 ? 1 : 0;
}

}  // namespace

void add_validate_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "validate", "Check the timing model against closed-form answers and published results");
  auto o = std::make_shared<ValidateOptions>();
  cmd->add_option("--config", o->config,
                  "Hardware config under test (default: defaults): " + kConfigForms);
  cmd->add_option("--set", o->sets, "Override a config key")->allow_extra_args(false);
  cmd->add_option("-o,--output", o->output, "Folder for validate.html, .md, .json and junit.xml");
  cmd->add_flag("--quick", o->quick, "The closed-form checks only (under 2 minutes)");
  cmd->add_option("--only", o->only,
                  "Only the checks whose id starts with PREFIX (e.g. vendor, ladder.l1_hit, "
                  "ceiling); a comma-separated list or the option repeated")
      ->delimiter(',')
      ->allow_extra_args(false);
  cmd->callback([o, &exit_code] { exit_code = run_validate(*o); });
}

}  // namespace rtsim::app
