// rtsim regress SUITE.toml --baseline DIR [--update-baseline]: runs every case of a regression
// suite (a workload on a hardware config, in parallel), checks each one's verification, and
// compares its metrics with the stored baseline under the suite's per-metric tolerances. Prints
// the delta table, writes OUT/junit.xml, OUT/regress.json and OUT/deltas.md, and exits 1 on a
// regression or a verification failure. --update-baseline records DIR/baseline.json instead.
#include <filesystem>
#include <memory>

#include <fmt/core.h>

#include "app/commands.h"
#include "model/sc/sim_report.h"
#include "reports/metrics.h"
#include "reports/page_util.h"
#include "reports/process_pool.h"
#include "reports/regress_compare.h"
#include "reports/report_writer.h"
#include "traces/output_file.h"
#include "traces/error.h"
#include "traces/hash.h"

namespace rtsim::app {
namespace {
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

struct RegressOptions {
  std::string suite, baseline, output = "regress-out", junit;
  std::vector<std::string> sets;
  uint32_t jobs = 0;
  bool update = false, quiet = false;
};

std::vector<std::string> case_argv(const reports::RegressCase& c, const std::string& trace,
                                   const std::string& dir, const RegressOptions& o) {
  std::vector<std::string> argv =
      reports::run_child_argv(trace, dir, c.fidelity, c.sampling.rate, c.config);
  for (const std::string& s : c.sets) argv.insert(argv.end(), {"--set", s});
  for (const std::string& s : o.sets) argv.insert(argv.end(), {"--set", s});
  return argv;
}

std::vector<reports::CaseOutcome> run_cases(const reports::RegressSuite& suite,
                                            const RegressOptions& o) {
  std::vector<reports::ProcessJob> jobs;
  std::vector<reports::CaseOutcome> cases;
  for (const reports::RegressCase& c : suite.cases) {
    load_hw_config(c.config, [&] {
      std::vector<std::string> all = c.sets;
      all.insert(all.end(), o.sets.begin(), o.sets.end());
      return all;
    }());
    std::string key = reports::read_file(c.trace.workload) + c.trace.workload + c.trace.resolution +
                      std::to_string(c.trace.frames) + c.trace.scene +
                      (c.trace.seed ? std::to_string(*c.trace.seed) : "");
    std::string trace = o.output + "/traces/" + text_hash(key);
    reports::trace_into(c.trace, trace, o.quiet);
    std::string dir = o.output + "/cases/" + c.name;
    fs::remove(dir + "/report.json");
    fs::create_directories(dir);
    jobs.push_back({case_argv(c, trace, dir, o), dir + "/run.log"});
    cases.push_back({c.name, false, 0, Json(), 0});
  }
  uint32_t parallel = o.jobs ? o.jobs : reports::local_cores();
  reports::run_processes(jobs, parallel, [&](size_t i, int code, double seconds) {
    reports::CaseOutcome& c = cases[i];
    c.exit_code = code;
    c.seconds = seconds;
    Json report = reports::whole_report(o.output + "/cases/" + c.name + "/report.json");
    c.ran = !report.is_null();
    if (c.ran) c.metrics = reports::flat_metrics(report);
    if (!o.quiet)
      fmt::print(
          "case       {}: {}\n", c.name,
          c.ran ? fmt::format("{} cycles",
                              reports::show(c.metrics["cycles"], reports::Style::Integer))
                : fmt::format("FAILED (exit {}, see {}/cases/{}/run.log)", code, o.output, c.name));
  });
  return cases;
}

int update_baseline(const reports::RegressSuite& suite, const RegressOptions& o,
                    const std::vector<reports::CaseOutcome>& cases) {
  for (const reports::CaseOutcome& c : cases) {
    const Json& u = reports::at_key(c.metrics, "unexplained");
    if (!c.ran || (suite.verify && (u.is_null() || u.get<uint64_t>() > 0))) {
      fmt::print(stderr, "rtsim regress: case {} failed or did not verify; baseline not written\n",
                 c.name);
      return 1;
    }
  }
  fs::create_directories(o.baseline);
  write_file_atomic(o.baseline + "/baseline.json",
                    reports::baseline_json(suite, cases).dump(2) + "\n");
  if (!o.quiet)
    fmt::print("baseline   {} cases recorded in {}/baseline.json\n", cases.size(), o.baseline);
  return 0;
}

int run_regress(const RegressOptions& o) {
  if (o.baseline.empty()) throw InputError("regress: --baseline DIR is required");
  if (o.update && !o.junit.empty())
    throw InputError(
        "regress: --junit goes with a comparison, not --update-baseline (which "
        "writes no JUnit XML)");
  reports::RegressSuite suite = reports::read_regress_suite(o.suite);
  create_output_folder(o.output);
  lock_output_folder(o.output, "rtsim regress");
  if (o.update) create_output_folder(o.baseline);
  if (o.update) lock_output_folder(o.baseline, "rtsim regress --update-baseline");
  if (!o.junit.empty())
    create_output_folder(fs::path(o.junit).parent_path().empty()
                             ? std::string(".")
                             : fs::path(o.junit).parent_path().string());
  Json baseline;
  if (!o.update) {
    std::string path = o.baseline + "/baseline.json";
    if (!fs::exists(path))
      throw_input_error(o.baseline, "", "no baseline.json (record one with --update-baseline)");
    baseline = reports::read_json_file(path, reports::kBaselineSchema);
    reports::require_fields(
        baseline, path,
        {{"cases", reports::JsonKind::Object}, {"cases.*.metrics", reports::JsonKind::Object}});
  }
  fs::create_directories(o.output);
  std::vector<reports::CaseOutcome> cases = run_cases(suite, o);
  if (o.update) return update_baseline(suite, o, cases);
  reports::RegressResult result = reports::compare_with_baseline(suite, cases, baseline);
  std::string junit = o.junit.empty() ? o.output + "/junit.xml" : o.junit;
  write_file_atomic(junit, reports::junit_xml(suite, result));
  write_file_atomic(o.output + "/regress.json",
                    reports::regress_json(suite, result).dump(2) + "\n");
  write_file_atomic(o.output + "/deltas.md",
                    "# rtsim regress: " + suite.name + "\n\n" + reports::delta_table(result, true));
  if (!o.quiet) {
    fmt::print("\n{}", reports::delta_table(result, false));
    fmt::print("\nregress    {}: {}; JUnit XML in {}\n", suite.name,
               result.failed() ? "FAILED" : "passed", junit);
  }
  return result.failed() ? 1 : 0;
}

}  // namespace

void add_regress_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "regress", "Run a regression suite and compare every metric with a stored baseline");
  auto o = std::make_shared<RegressOptions>();
  cmd->add_option("suite", o->suite, "Regression suite (.toml; see reports/examples/)")->required();
  cmd->add_option("--baseline", o->baseline, "Baseline folder (baseline.json)");
  cmd->add_flag("--update-baseline", o->update, "Record the runs as the new baseline");
  cmd->add_option("-o,--output", o->output, "Folder for runs, junit.xml, regress.json, deltas.md")
      ->capture_default_str();
  cmd->add_option("--junit", o->junit, "JUnit XML path (default: OUTPUT/junit.xml)");
  cmd->add_option("--set", o->sets, "Override a config key in every case")->allow_extra_args(false);
  cmd->add_option("-j,--jobs", o->jobs, "Cases run at once (default: all cores)");
  cmd->add_flag("-q,--quiet", o->quiet, "Print nothing but errors (the exit code is the verdict)");
  cmd->callback([o, &exit_code] { exit_code = run_regress(*o); });
}

}  // namespace rtsim::app
