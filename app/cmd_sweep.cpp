// rtsim sweep SPEC.toml -o DIR: runs every workload x hardware point of a sweep spec (a grid or
// a list over config keys), in parallel on the local cores, resuming an interrupted sweep
// without redoing finished points, and writes DIR/sweep.{json,csv,html,md} with curves and a
// Pareto chart. Exit 1 if a point failed or its verification found an unexplained mismatch.
#include <memory>

#include <fmt/core.h>

#include "app/commands.h"
#include "reports/sweep_report.h"
#include "reports/sweep_spec.h"
#include "traces/output_file.h"
#include "traces/error.h"

namespace rtsim::app {
namespace {

struct SweepOptions {
  std::string spec, output;
  uint32_t jobs = 0;
  uint64_t max_points = reports::kDefaultMaxSweepPoints;
  bool no_charts = false, quiet = false;
};

int run_sweep_command(const SweepOptions& o) {
  if (o.output.empty()) throw InputError("sweep: -o DIR is required");
  reports::SweepSpec spec = reports::read_sweep_spec(o.spec, o.max_points);
  create_output_folder(o.output);
  lock_output_folder(o.output, "rtsim sweep");
  std::vector<reports::PointRun> points = reports::run_sweep(spec, {o.output, o.jobs, o.quiet});
  nlohmann::ordered_json doc = reports::sweep_json(spec, points);
  reports::ReportOutcome out = reports::write_sweep_report(doc, o.output, {!o.no_charts, true});
  size_t failed = 0, unverified = 0;
  for (const reports::PointRun& p : points) {
    failed += !p.ok;
    const auto& u = p.metrics.is_object() ? p.metrics["unexplained"] : nlohmann::ordered_json();
    unverified += p.ok && !u.is_null() && u.get<uint64_t>() > 0;
  }
  if (!o.quiet) {
    if (!out.charts_ok) fmt::print("charts     missing: {}\n", out.message);
    fmt::print(
        "sweep      {} points: {} failed, {} with unexplained mismatches; results in "
        "{}/sweep.html, sweep.csv, sweep.json\n",
        points.size(), failed, unverified, o.output);
  }
  return failed + unverified > 0 ? 1 : 0;
}

}  // namespace

void add_sweep_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "sweep", "Run a grid or list of hardware points over workloads, in parallel, resumable");
  auto o = std::make_shared<SweepOptions>();
  cmd->add_option("spec", o->spec, "Sweep spec (.toml; see reports/examples/)")->required();
  cmd->add_option("-o,--output", o->output, "Sweep folder (results, points, traces)");
  cmd->add_option("-j,--jobs", o->jobs, "Points run at once (default: the spec's, else all cores)");
  cmd->add_option("--max-points", o->max_points,
                  "Refuse a grid of more points than this (counted before it is expanded)")
      ->check(CLI::Range(uint64_t(1), uint64_t(1) << 40));
  cmd->add_flag("--no-charts", o->no_charts, "Write the pages without running Python");
  cmd->add_flag("-q,--quiet", o->quiet, "Print nothing but errors");
  cmd->callback([o, &exit_code] { exit_code = run_sweep_command(*o); });
}

}  // namespace rtsim::app
